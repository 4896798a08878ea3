#include "ui/export.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>

#include <QBuffer>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>

#include "qcustomplot.h"
#include "simlab/output.h"
#include "ui/plot_series.h"

namespace elui {

namespace {

// Where an export's bytes go. A file goes through QSaveFile: a temporary sibling, renamed over
// the target on commit, so a failed or interrupted write leaves the old file as it was and no
// partial file behind. An existing device (/dev/null, /dev/full, a terminal) is written in
// place: QSaveFile would create its temporary file beside the device and rename it over the
// device node (for a user allowed to write in /dev, e.g. root) — a device cannot be replaced.
//
// Every write is checked, and so is the final flush: Qt 6.4 does not. A write cut short by a
// full disk returns fewer bytes without setting an error, and QSaveFile::commit() ignores a
// failed flush of its buffer — both rename the truncated temporary file over the old one
// (seen in test_gui_files: the old file became the first 1024 bytes of the new one).
class Output {
public:
    explicit Output(const QString& path) : m_path(path) {
        const QFileInfo info(path);
        if (info.exists() && !info.isFile() && !info.isDir()) m_file = std::make_unique<QFile>(path);
        else m_file = std::make_unique<QSaveFile>(path);
    }

    // An error message naming the file and the system's reason, or empty.
    QString open() {
        if (!m_file->open(QIODevice::WriteOnly))
            return QObject::tr("Could not open %1: %2").arg(m_path, m_file->errorString());
        return {};
    }
    void write(const char* data, qint64 size) {
        if (m_failed) return;
        if (m_file->write(data, size) != size) fail();
    }
    void write(const QByteArray& bytes) { write(bytes.constData(), bytes.size()); }
    QString commit() {
        if (!m_failed && !m_file->flush()) fail();
        if (m_failed) {
            if (auto* save = qobject_cast<QSaveFile*>(m_file.get())) {
                save->cancelWriting();
                save->commit();  // cancelled: removes the temporary file, renames nothing
            } else {
                m_file->close();
            }
            return QObject::tr("Could not write %1: %2").arg(m_path, m_reason);
        }
        bool ok = false;
        if (auto* save = qobject_cast<QSaveFile*>(m_file.get())) {
            ok = save->commit();
        } else {
            m_file->close();
            ok = m_file->error() == QFileDevice::NoError;
        }
        if (!ok) return QObject::tr("Could not write %1: %2").arg(m_path, m_file->errorString());
        return {};
    }

private:
    void fail() {
        // A short write leaves Qt's error text empty ("Unknown error"); errno still holds the
        // system's reason (ENOSPC, EFBIG, EIO).
        const int error = errno;
        m_failed = true;
        m_reason = m_file->errorString();
        if (m_file->error() == QFileDevice::NoError || m_reason == QFile().errorString())
            m_reason = error != 0 ? QString::fromLocal8Bit(std::strerror(error))
                                  : QObject::tr("the data was not written completely");
    }

    QString m_path;
    std::unique_ptr<QFileDevice> m_file;
    bool m_failed = false;
    QString m_reason;
};

// Writes bytes encoded in memory first (images, PDF): an encoder never sees a failing disk, and
// what reaches the file is checked by Output.
QString writeEncoded(const QString& path, const QByteArray& bytes) {
    Output file(path);
    if (QString e = file.open(); !e.isEmpty()) return e;
    file.write(bytes);
    return file.commit();
}

QByteArray encodedImage(const QImage& image, const char* format) {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, format)) return {};
    return bytes;
}

// A plain SVG of the plots (polylines over a simple frame): no QtSvg needed.
QByteArray plotsSvg(const std::vector<QCustomPlot*>& plots, const std::vector<PlotSpec>& specs, int width,
                    int heightEach) {
    QString svg;
    const int height = heightEach * int(plots.size());
    svg += QStringLiteral("<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' "
                          "width='%1' height='%2' font-family='sans-serif' font-size='12'>\n")
               .arg(width)
               .arg(height);
    svg += QStringLiteral("<rect width='100%' height='100%' fill='white'/>\n");
    for (std::size_t p = 0; p < plots.size(); ++p) {
        QCustomPlot* plot = plots[p];
        const double top = double(p) * heightEach, left = 70, right = width - 20, bottom = top + heightEach - 40;
        const double plotTop = top + 30;
        const QCPRange xr = plot->xAxis->range(), yr = plot->yAxis->range();
        auto sx = [&](double x) { return left + (x - xr.lower) / (xr.upper - xr.lower) * (right - left); };
        auto sy = [&](double y) { return bottom - (y - yr.lower) / (yr.upper - yr.lower) * (bottom - plotTop); };
        svg += QStringLiteral("<text x='%1' y='%2' font-weight='bold'>%3</text>\n")
                   .arg(left).arg(top + 18).arg(specs[p].title.toHtmlEscaped());
        svg += QStringLiteral("<rect x='%1' y='%2' width='%3' height='%4' fill='none' stroke='black'/>\n")
                   .arg(left).arg(plotTop).arg(right - left).arg(bottom - plotTop);
        for (int i = 0; i <= 4; ++i) {
            const double yv = yr.lower + (yr.upper - yr.lower) * i / 4.0;
            const double xv = xr.lower + (xr.upper - xr.lower) * i / 4.0;
            svg += QStringLiteral("<text x='%1' y='%2' text-anchor='end'>%3</text>\n")
                       .arg(left - 4).arg(sy(yv) + 4).arg(QString::number(yv, 'g', 4));
            svg += QStringLiteral("<text x='%1' y='%2' text-anchor='middle'>%3</text>\n")
                       .arg(sx(xv)).arg(bottom + 16).arg(QString::number(xv, 'g', 4));
        }
        svg += QStringLiteral("<text x='%1' y='%2' text-anchor='middle'>t [s]</text>\n")
                   .arg((left + right) / 2).arg(bottom + 32);
        svg += QStringLiteral("<text x='14' y='%1' transform='rotate(-90 14 %1)' text-anchor='middle'>%2</text>\n")
                   .arg((plotTop + bottom) / 2).arg(specs[p].yLabel.toHtmlEscaped());
        svg += QStringLiteral("<clipPath id='c%1'><rect x='%2' y='%3' width='%4' height='%5'/></clipPath>\n")
                   .arg(p).arg(left).arg(plotTop).arg(right - left).arg(bottom - plotTop);
        // The series themselves (not the faint abandoned future after them).
        const int series = std::min(plot->graphCount(), int(specs[p].series.size()));
        for (int g = 0; g < series; ++g) {
            QCPGraph* graph = plot->graph(g);
            QString points;
            // At most ~2000 points per series: enough for any printed width.
            auto data = graph->data();
            auto begin = data->findBegin(xr.lower), end = data->findEnd(xr.upper);
            const int n = int(end - begin);
            const int stride = std::max(1, n / 2000);
            for (auto it = begin; it < end; it += stride)
                if (std::isfinite(it->value)) points += QStringLiteral("%1,%2 ").arg(sx(it->key), 0, 'f', 1).arg(sy(it->value), 0, 'f', 1);
            svg += QStringLiteral("<polyline clip-path='url(#c%1)' fill='none' stroke='%2' stroke-width='%3' points='%4'/>\n")
                       .arg(p).arg(graph->pen().color().name()).arg(graph->pen().widthF()).arg(points);
            svg += QStringLiteral("<text x='%1' y='%2' fill='%3'>%4</text>\n")
                       .arg(left + 8 + 80 * g).arg(plotTop + 16).arg(graph->pen().color().name())
                       .arg(graph->name().toHtmlEscaped());
        }
    }
    svg += QStringLiteral("</svg>\n");
    return svg.toUtf8();
}

}  // namespace

QString writeCsv(const QString& path, simcore::SceneKind kind, const std::vector<simcore::Diagnostics>& rows) {
    // Streamed row by row (a long history is hundreds of MB).
    Output file(path);
    if (QString e = file.open(); !e.isEmpty()) return e;
    const auto columns = simlab::timeSeriesColumns(kind);
    const std::string header = simlab::csvHeader(columns);
    file.write(header.data(), qint64(header.size()));
    for (const simcore::Diagnostics& d : rows) {
        const std::string row = simlab::csvRow(columns, d);
        file.write(row.data(), qint64(row.size()));
    }
    return file.commit();
}

QString writeFile(const QString& path, const QByteArray& bytes) { return writeEncoded(path, bytes); }

QString writeImage(const QString& path, const QImage& image) {
    const QByteArray format = QFileInfo(path).suffix().toLower().toLatin1();
    const QByteArray bytes = encodedImage(image, format.isEmpty() ? "PNG" : format.constData());
    if (bytes.isEmpty()) return QObject::tr("Could not encode %1 as %2").arg(path, format.isEmpty() ? "PNG" : format);
    return writeEncoded(path, bytes);
}

QString writePlots(const QString& path, const std::vector<QCustomPlot*>& plots, const std::vector<PlotSpec>& specs,
                   int width, int heightEach) {
    if (plots.empty()) return QObject::tr("No plot to export");
    const QString suffix = QFileInfo(path).suffix().toLower();
    QByteArray bytes;
    if (suffix == QLatin1String("svg")) {
        bytes = plotsSvg(plots, specs, width, heightEach);
    } else if (suffix == QLatin1String("pdf")) {
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        QPdfWriter writer(&buffer);
        writer.setPageSize(QPageSize(QSizeF(width, heightEach * double(plots.size())), QPageSize::Point));
        writer.setPageMargins(QMarginsF(0, 0, 0, 0));
        writer.setResolution(72);
        QCPPainter painter(&writer);
        for (std::size_t i = 0; i < plots.size(); ++i) {
            painter.save();
            painter.translate(0, double(i) * heightEach);
            plots[i]->toPainter(&painter, width, heightEach);
            painter.restore();
        }
        painter.end();
    } else {
        QImage image(width, heightEach * int(plots.size()), QImage::Format_ARGB32);
        image.fill(Qt::white);
        QPainter painter(&image);
        for (std::size_t i = 0; i < plots.size(); ++i)
            painter.drawPixmap(0, int(i) * heightEach, plots[i]->toPixmap(width, heightEach));
        painter.end();
        bytes = encodedImage(image, "PNG");
    }
    if (bytes.isEmpty()) return QObject::tr("Could not encode %1").arg(path);
    return writeEncoded(path, bytes);
}

}  // namespace elui
