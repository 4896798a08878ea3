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
#include <QSvgGenerator>

#include "qcustomplot.h"
#include "simlab/output.h"
#include "ui/plot_series.h"
#include "simlab/timeseries.h"

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

}  // namespace

QString writeCsv(const QString& path, simcore::SceneKind kind, const std::vector<simcore::Diagnostics>& rows,
                 simlab::CsvDialect dialect) {
    // Streamed row by row (a long history is hundreds of MB).
    Output file(path);
    if (QString e = file.open(); !e.isEmpty()) return e;
    const auto columns = simlab::timeSeriesColumns(kind);
    const std::string header = simlab::inDialect(simlab::csvHeader(columns), dialect, true);
    file.write(header.data(), qint64(header.size()));
    for (const simcore::Diagnostics& d : rows) {
        const std::string row = simlab::inDialect(simlab::csvRow(columns, d), dialect, false);
        file.write(row.data(), qint64(row.size()));
    }
    return file.commit();
}

QString writeXlsx(const QString& path, simcore::SceneKind kind, const std::vector<simcore::Diagnostics>& rows) {
    simlab::TimeSeriesWriter writer(kind, simlab::timeSeriesColumns(kind), {{}, {}, path.toStdString()});
    for (const simcore::Diagnostics& d : rows) {
        if (!writer.ok()) break;
        writer.add(d);
    }
    if (!writer.commit()) return QString::fromStdString(writer.error());
    return {};
}

simlab::CsvDialect defaultCsvDialect(const QLocale& locale) {
    return locale.decimalPoint() == QLatin1String(",") ? simlab::CsvDialect::ExcelSemicolon
                                                       : simlab::CsvDialect::Plain;
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
    // SVG and PDF: the plots as drawn on screen, through Qt's own vector painters (Qt SVG's
    // generator escapes every text it writes; the hand-written SVG it replaces broke on a
    // title or legend with "&" or "<").
    auto paint = [&](QPaintDevice* device) {
        QCPPainter painter(device);
        for (std::size_t i = 0; i < plots.size(); ++i) {
            painter.save();
            painter.translate(0, double(i) * heightEach);
            plots[i]->toPainter(&painter, width, heightEach);
            painter.restore();
        }
        painter.end();
    };
    if (suffix == QLatin1String("svg")) {
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        QSvgGenerator generator;
        generator.setOutputDevice(&buffer);
        generator.setSize(QSize(width, heightEach * int(plots.size())));
        generator.setViewBox(QRect(0, 0, width, heightEach * int(plots.size())));
        QStringList titles;
        for (const PlotSpec& spec : specs) titles << spec.title;
        generator.setTitle(titles.join(QStringLiteral(", ")));
        generator.setDescription(QStringLiteral("Elastic Lab plots"));
        paint(&generator);
    } else if (suffix == QLatin1String("pdf")) {
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        QPdfWriter writer(&buffer);
        writer.setPageSize(QPageSize(QSizeF(width, heightEach * double(plots.size())), QPageSize::Point));
        writer.setPageMargins(QMarginsF(0, 0, 0, 0));
        writer.setResolution(72);
        paint(&writer);
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
