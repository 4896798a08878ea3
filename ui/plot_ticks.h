#pragma once
// Tick labels that stay apart. QCustomPlot's tickers aim at a tick count whatever the axis's
// length and the labels' width, so a narrow dock or a larger font (presentation mode) makes
// neighbouring numbers run into each other ("-500-2500"). keepTickLabelsApart() asks the
// ticker, at every replot (once the layout is known), for the most ticks up to the wanted count whose labels fit side
// by side with a gap of half a letter (or, on a vertical axis, one above the other).

class QCPAxis;

namespace elui {

// Installs the check on `axis` (a numeric axis, linear or logarithmic: its ticker's tick count
// is the most it shows).
void keepTickLabelsApart(QCPAxis* axis);
// A logarithmic axis whose labels stay apart (three significant digits, and keepTickLabelsApart):
// the study diagrams' axes.
void setLogTicks(QCPAxis* axis);
// Whether two neighbouring tick labels of a drawn axis overlap, measured with the axis's tick
// label font at the ticks' pixel positions (for the tests).
bool tickLabelsOverlap(const QCPAxis* axis);

}  // namespace elui
