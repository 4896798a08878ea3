#include "ui/plot_ticks.h"

#include <cmath>

#include <QFontMetricsF>

#include "qcustomplot.h"

namespace elui {

namespace {
bool horizontal(const QCPAxis* axis) { return axis->orientation() == Qt::Horizontal; }

// Whether labels at `ticks` fit the axis as it is laid out now.
bool fits(const QCPAxis* axis, const QVector<double>& ticks, const QVector<QString>& labels) {
    // The labels' ink (tight bounding boxes), apart by half a letter across, one pixel above
    // one another.
    const QFontMetricsF fm(axis->tickLabelFont());
    const double gap = horizontal(axis) ? 0.5 * fm.horizontalAdvance(QLatin1Char('M')) : 1.0;
    double lastPixel = 0.0, lastHalf = 0.0;
    bool first = true;
    for (int i = 0; i < ticks.size() && i < labels.size(); ++i) {
        if (!axis->range().contains(ticks[i])) continue;
        const double pixel = axis->coordToPixel(ticks[i]);
        const QRectF ink = fm.tightBoundingRect(labels[i]);
        const double half = 0.5 * (horizontal(axis) ? ink.width() : ink.height());
        if (!first && std::abs(pixel - lastPixel) < lastHalf + half + gap) return false;
        first = false;
        lastPixel = pixel;
        lastHalf = half;
    }
    return true;
}
}  // namespace

void keepTickLabelsApart(QCPAxis* axis) {
    const int wanted = std::max(2, axis->ticker()->tickCount());
    QCustomPlot* plot = axis->parentPlot();
    // After the layout, on the axis rect this replot draws into: the ticks were made before
    // the layout (for the previous size and font); when another count fits better they are
    // made again for this draw.
    QObject::connect(plot, &QCustomPlot::afterLayout, axis, [axis, wanted] {
        const int length = horizontal(axis) ? axis->axisRect()->width() : axis->axisRect()->height();
        if (length < 20) return;
        const QSharedPointer<QCPAxisTicker> ticker = axis->ticker();
        const int before = ticker->tickCount();
        const QString format = axis->numberFormat();
        for (int n = wanted; n >= 2; --n) {
            ticker->setTickCount(n);
            QVector<double> ticks;
            QVector<QString> labels;
            ticker->generate(axis->range(), axis->parentPlot()->locale(), format.isEmpty() ? QLatin1Char('g') : format.at(0),
                             axis->numberPrecision(), ticks, nullptr, &labels);
            if (fits(axis, ticks, labels)) break;
        }
        if (ticker->tickCount() != before) axis->axisRect()->update(QCPLayoutElement::upPreparation);
    });
}

void setLogTicks(QCPAxis* axis) {
    axis->setScaleType(QCPAxis::stLogarithmic);
    axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    // Three significant digits: over less than 1.6 decades QCustomPlot's log ticker falls back
    // to linear steps (0.008, 0.01, 0.012), which a one-digit mantissa printed as "10⁻²" three
    // times. Powers of ten still read 0.001, 0.01, 1e+05 (beautified to 10⁵).
    axis->setNumberFormat(QStringLiteral("gb"));
    axis->setNumberPrecision(3);
    // Those linear steps' labels are long (0.0125, 0.015, 0.0175): fewer of them where they
    // would run into each other.
    keepTickLabelsApart(axis);
}

bool tickLabelsOverlap(const QCPAxis* axis) { return !fits(axis, axis->tickVector(), axis->tickVectorLabels()); }

}  // namespace elui
