#pragma once
// The UI scale (View > Presentation mode, Ctrl+= / Ctrl+-): every text of the window grows by one
// factor, so a class at the back of the room can read it on a projector.
//
// Qt cannot change its device-pixel ratio at run time (QT_SCALE_FACTOR is read at start), so the
// scale is carried by the fonts: the application font is the start font times the factor, every
// widget without a font of its own follows it, and the layouts grow with their text. What does
// not follow the application font is scaled here by the same factor: the QCustomPlots' axes,
// legends, titles and items (QCustomPlot copies its widget's font once, when a plot is made) and
// widgets with a point size of their own. Minimum sizes in pixels stay as they are.

#include <QFont>

class QWidget;
class QCustomPlot;

namespace elui {

// The steps Ctrl+= and Ctrl+- go through; 1 is the normal size, 1.25 .. 2 presentation sizes.
inline constexpr double kUiScales[] = {1.0, 1.25, 1.5, 1.75, 2.0};
// Presentation mode switched on from the normal size.
inline constexpr double kPresentationScale = 1.5;

// The scale now in use (1 until setUiScale was called).
double uiScale();
// Sets the scale (clamped to [1, 2]): the application font becomes the start font times it, and
// every existing QCustomPlot's fonts follow. Plots made later take the application font (and so
// the scale) when they are made.
void setUiScale(double scale);
// The next step up or down from the current scale (the same value at either end).
double nextUiScale(double current, int direction);
// The start font (the application font at scale 1).
QFont baseUiFont();
// A QCustomPlot's fonts from the scale they were made at to the current one (setUiScale does
// this for every plot there is; exported for the tests).
void scalePlotFonts(QCustomPlot* plot);

}  // namespace elui
