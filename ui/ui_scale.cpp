#include "ui/ui_scale.h"

#include <algorithm>
#include <cmath>

#include <QApplication>
#include <QWidget>

#include "qcustomplot.h"

namespace elui {

namespace {
double g_scale = 1.0;
QFont g_base;
bool g_haveBase = false;

QFont scaled(QFont font, double factor) {
    if (font.pointSizeF() > 0) font.setPointSizeF(font.pointSizeF() * factor);
    else if (font.pixelSize() > 0) font.setPixelSize(std::max(1, int(std::lround(font.pixelSize() * factor))));
    return font;
}

// Every font a QCustomPlot holds, times `factor`.
void scalePlot(QCustomPlot* plot, double factor) {
    for (QCPAxisRect* rect : plot->axisRects())
        for (QCPAxis* axis : rect->axes()) {
            axis->setLabelFont(scaled(axis->labelFont(), factor));
            axis->setTickLabelFont(scaled(axis->tickLabelFont(), factor));
            axis->setSelectedLabelFont(scaled(axis->selectedLabelFont(), factor));
            axis->setSelectedTickLabelFont(scaled(axis->selectedTickLabelFont(), factor));
        }
    // Legends (the plot's own and any in an inset), titles and other text elements.
    for (QCPLayoutElement* element : plot->plotLayout()->elements(true)) {
        if (auto* text = qobject_cast<QCPTextElement*>(element)) {
            text->setFont(scaled(text->font(), factor));
            text->setSelectedFont(scaled(text->selectedFont(), factor));
        } else if (auto* legend = qobject_cast<QCPLegend*>(element)) {
            const QFont font = scaled(legend->font(), factor);
            legend->setSelectedFont(scaled(legend->selectedFont(), factor));
            legend->setFont(font);  // and every item's
        }
    }
    for (QCPAxisRect* rect : plot->axisRects())
        for (QCPLayoutElement* element : rect->insetLayout()->elements(true))
            if (auto* legend = qobject_cast<QCPLegend*>(element)) legend->setFont(scaled(legend->font(), factor));
    for (int i = 0; i < plot->itemCount(); ++i)
        if (auto* text = qobject_cast<QCPItemText*>(plot->item(i))) {
            text->setFont(scaled(text->font(), factor));
            text->setSelectedFont(scaled(text->selectedFont(), factor));
        }
}

const char* const kPlotScale = "elasticLabUiScale";

void scalePlotFrom(QCustomPlot* plot, double assumed) {
    // A plot not yet tagged was made under the application font of the scale before this change.
    const QVariant tag = plot->property(kPlotScale);
    const double from = tag.isValid() ? tag.toDouble() : assumed;
    if (from != g_scale) scalePlot(plot, g_scale / from);
    plot->setProperty(kPlotScale, g_scale);
}
}  // namespace

double uiScale() { return g_scale; }

QFont baseUiFont() {
    if (!g_haveBase) {
        g_base = QApplication::font();
        g_haveBase = true;
    }
    return g_base;
}

double nextUiScale(double current, int direction) {
    const auto* begin = std::begin(kUiScales);
    const auto* end = std::end(kUiScales);
    if (direction > 0) {
        const auto* it = std::upper_bound(begin, end, current + 1e-9);
        return it == end ? kUiScales[std::size(kUiScales) - 1] : *it;
    }
    const auto* it = std::lower_bound(begin, end, current - 1e-9);
    return it == begin ? kUiScales[0] : *(it - 1);
}

void scalePlotFonts(QCustomPlot* plot) { scalePlotFrom(plot, g_scale); }

void setUiScale(double scale) {
    scale = std::clamp(scale, 1.0, 2.0);
    if (scale == g_scale) return;
    const QFont base = baseUiFont();
    const double previous = g_scale;
    const double factor = scale / previous;
    const QWidgetList widgets = QApplication::allWidgets();
    // Widgets with a size of their own (a bold title, a small note) do not follow the
    // application font: they grow by the same factor.
    for (QWidget* w : widgets)
        if (w->testAttribute(Qt::WA_SetFont) && (w->font().resolveMask() & QFont::SizeResolved))
            w->setFont(scaled(w->font(), factor));
    g_scale = scale;
    QApplication::setFont(scaled(base, scale));
    for (QWidget* w : widgets)
        if (auto* plot = qobject_cast<QCustomPlot*>(w)) {
            scalePlotFrom(plot, previous);
            plot->replot(QCustomPlot::rpQueuedReplot);
        }
}

}  // namespace elui
