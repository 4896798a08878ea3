#include "simlab/timeseries.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include <xlsxwriter.h>

namespace simlab {

// The workbook under construction: libxlsxwriter needs a file name, so it writes to a private
// temporary file (mkstemp in the system's temporary folder); commit() copies the finished bytes
// through the target's AtomicFile, opened up front so that a bad path is found before the run.
class TimeSeriesWriter::Xlsx {
public:
    Xlsx(const std::string& path, simcore::SceneKind kind, const std::vector<CsvColumn>& columns)
        : m_target(path), m_kind(kind), m_columns(columns) {
        if (!m_target.ok()) {
            m_error = m_target.error();
            return;
        }
        const char* folder = std::getenv("TMPDIR");
        m_temp = std::string(folder && *folder ? folder : "/tmp") + "/elastic-lab-xlsx-XXXXXX";
        const int fd = ::mkstemp(m_temp.data());
        if (fd < 0) {
            m_error = "cannot write '" + path + "': no temporary file (" + std::strerror(errno) + ")";
            m_temp.clear();
            return;
        }
        ::close(fd);
        lxw_workbook_options options{};
        options.constant_memory = LXW_TRUE;
        options.tmpdir = nullptr;
        m_book = workbook_new_opt(m_temp.c_str(), &options);
        m_sheet = m_book ? workbook_add_worksheet(m_book, "run") : nullptr;
        if (!m_sheet) {
            m_error = "cannot write '" + path + "': the workbook could not be created";
            return;
        }
        lxw_format* bold = workbook_add_format(m_book);
        format_set_bold(bold);
        worksheet_freeze_panes(m_sheet, 1, 0);
        for (std::size_t c = 0; c < columns.size(); ++c) {
            const std::string header = headerWithUnit(columns[c]);
            worksheet_write_string(m_sheet, 0, static_cast<lxw_col_t>(c), header.c_str(), bold);
        }
        worksheet_set_column(m_sheet, 0, static_cast<lxw_col_t>(columns.size() - 1), 14, nullptr);
    }
    ~Xlsx() {
        if (m_book) workbook_close(m_book);  // only on failure: commit() closes and clears it
        if (!m_temp.empty()) std::remove(m_temp.c_str());
    }

    const std::string& error() const { return m_error; }

    void add(const simcore::Diagnostics& d, long row) {
        if (!m_error.empty()) return;
        if (row > kXlsxMaxDataRows) {
            m_error = "cannot write '" + m_target.path() + "': an .xlsx sheet holds at most " +
                      std::to_string(kXlsxMaxDataRows) + " rows of data; write fewer (every N steps)";
            return;
        }
        for (std::size_t c = 0; c < m_columns.size(); ++c) {
            const double v = m_columns[c].value(d);
            if (!std::isfinite(v)) continue;  // an empty cell (the CSV never gets here: failures stop first)
            worksheet_write_number(m_sheet, static_cast<lxw_row_t>(row), static_cast<lxw_col_t>(c), v, nullptr);
        }
        m_rows = row;
    }

    bool commit() { return finish() && commitTarget(); }
    bool commitTarget() {
        if (!m_target.commit()) {
            m_error = m_target.error();
            return false;
        }
        return true;
    }
    AtomicFile& target() { return m_target; }
    bool finish() {
        if (m_finished) return m_error.empty();
        m_finished = true;
        if (!m_error.empty()) return false;
        addCharts();
        errno = 0;
        const lxw_error closed = workbook_close(m_book);
        const int reason = errno;  // the system's reason behind libxlsxwriter's (EFBIG, ENOSPC)
        m_book = nullptr;
        if (closed != LXW_NO_ERROR) {
            m_error = "cannot write '" + m_target.path() + "': " + lxw_strerror(closed);
            if (reason != 0) m_error += std::string(" (") + std::strerror(reason) + ")";
            return false;
        }
        std::ifstream in(m_temp, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!in.good() && !in.eof()) {
            m_error = "cannot write '" + m_target.path() + "': the temporary workbook could not be read";
            return false;
        }
        if (!m_target.write(bytes)) {
            m_error = m_target.error();
            return false;
        }
        return true;
    }

private:
    int columnOf(const std::string& name) const {
        for (std::size_t c = 0; c < m_columns.size(); ++c)
            if (m_columns[c].name == name) return static_cast<int>(c);
        return -1;
    }

    // One scatter chart with straight lines per ChartSpec, on the sheet "charts", stacked.
    void addCharts() {
        const int t = columnOf("t");
        if (t < 0 || m_rows < 1) return;
        lxw_worksheet* sheet = workbook_add_worksheet(m_book, "charts");
        lxw_row_t at = 1;
        for (const ChartSpec& spec : timeSeriesCharts(m_kind)) {
            lxw_chart* chart = workbook_add_chart(m_book, LXW_CHART_SCATTER_STRAIGHT);
            for (const std::string& name : spec.columns) {
                const int c = columnOf(name);
                if (c < 0) continue;
                lxw_chart_series* series = chart_add_series(chart, nullptr, nullptr);
                chart_series_set_categories(series, "run", 1, static_cast<lxw_col_t>(t), static_cast<lxw_row_t>(m_rows),
                                            static_cast<lxw_col_t>(t));
                chart_series_set_values(series, "run", 1, static_cast<lxw_col_t>(c), static_cast<lxw_row_t>(m_rows),
                                        static_cast<lxw_col_t>(c));
                chart_series_set_name_range(series, "run", 0, static_cast<lxw_col_t>(c));
            }
            chart_title_set_name(chart, spec.title.c_str());
            chart_axis_set_name(chart->x_axis, "t [s]");
            chart_axis_set_name(chart->y_axis, spec.axis.c_str());
            chart_legend_set_position(chart, LXW_CHART_LEGEND_BOTTOM);
            lxw_chart_options placement{};
            placement.x_scale = 2.0;
            placement.y_scale = 1.5;
            worksheet_insert_chart_opt(sheet, at, 1, chart, &placement);
            at += 24;
        }
    }

    AtomicFile m_target;
    simcore::SceneKind m_kind;
    const std::vector<CsvColumn>& m_columns;
    std::string m_temp;
    lxw_workbook* m_book = nullptr;
    lxw_worksheet* m_sheet = nullptr;
    long m_rows = 0;
    std::string m_error;
    bool m_finished = false;
};

TimeSeriesWriter::TimeSeriesWriter(simcore::SceneKind kind, std::vector<CsvColumn> columns, TimeSeriesFiles files)
    : m_kind(kind), m_columns(std::move(columns)), m_files(std::move(files)) {
    if (!m_files.csv.empty()) {
        m_csv = std::make_unique<AtomicFile>(m_files.csv);
        if (!m_csv->ok()) fail(m_csv->error());
        else m_csv->write(inDialect(csvHeader(m_columns), m_files.dialect, true));
    }
    if (!m_files.xlsx.empty()) {
        m_xlsx = std::make_unique<Xlsx>(m_files.xlsx, m_kind, m_columns);
        if (!m_xlsx->error().empty()) fail(m_xlsx->error());
    }
}

TimeSeriesWriter::~TimeSeriesWriter() = default;

void TimeSeriesWriter::fail(const std::string& message) {
    if (m_error.empty()) m_error = message;
}

void TimeSeriesWriter::add(const simcore::Diagnostics& d) {
    ++m_rows;
    if (m_csv) m_csv->write(inDialect(csvRow(m_columns, d), m_files.dialect, false));
    if (m_xlsx) {
        m_xlsx->add(d, m_rows);
        if (!m_xlsx->error().empty()) fail(m_xlsx->error());
    }
}

bool TimeSeriesWriter::finish() {
    if (!ok()) return false;
    // The workbook first: it is the one that can still refuse (too many rows were found in add()).
    if (m_xlsx && !m_xlsx->finish()) fail(m_xlsx->error());
    return ok();
}

std::vector<AtomicFile*> TimeSeriesWriter::files() {
    std::vector<AtomicFile*> out;
    if (m_xlsx) out.push_back(&m_xlsx->target());
    if (m_csv) out.push_back(m_csv.get());
    return out;
}

bool TimeSeriesWriter::commit() {
    if (!finish()) return false;
    if (auto error = commitAll(files())) fail(*error);
    return ok();
}

}  // namespace simlab
