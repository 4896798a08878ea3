#pragma once
// Guided experiments (the Lessons menu, Help > Experiments, `elastic-lab --lesson ID`): a preset, the docks to
// look at, and a half-page text in resources/lessons/ID.html with the sections Goal, What to
// do, What to look at, The measured answer and Why.
//
// Every number a lesson states as its answer sits in a marked element,
//   <span class="answer" data-key="KEY" data-tol="0.03">0.0077</span>
// (data-tol: the relative tolerance of a re-measurement), next to the elastic-lab-cli command
// that measured it. tests/test_lessons.cpp re-measures each key with simcore and compares.
//
// Every value the text names in "What to do" is marked too:
//   <span class="setting" data-key="dt">0.006</span>   the preset sets it (checked against it)
//   <span class="try" data-key="dt">0.0075</span>      the student types it (a valid value)
//   <span class="until">3</span>                        run until this simulated time [s]
// test_lessons fails when a setting differs from the preset, a try is refused by the parameter
// table, or "= 5" / "to 5" is left unmarked in "What to do".

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

#include "ui/presets.h"

namespace elui {

struct Lesson {
    QString id;          // also accepted by --lesson
    QString title;       // list entry
    Preset preset;       // scene, parameters, integrator(s) (two or three: side by side), kick
    QStringList docks;   // MainWindow::openDock names to open besides the default docks

    // The text (HTML) from the resource :/lessons/<id>.html; empty if it is missing.
    QString html() const;
};

// A stated answer: the number as written and the tolerance of a re-measurement.
struct LessonAnswer {
    double value = 0.0;
    double relativeTolerance = 0.0;
};

QList<Lesson> lessons();
const Lesson* findLesson(const QString& id);
QStringList lessonIds();

// The section headings (<h3>) a lesson text must have, in this order.
QStringList lessonSectionTitles();
// The <h3> headings of a text, in order.
QStringList lessonSections(const QString& html);
// The marked answers of a text by key; *error names the first malformed one (a key twice, a
// value or tolerance that is not a number).
QMap<QString, LessonAnswer> lessonAnswers(const QString& html, QString* error = nullptr);

// A marked value of "What to do": class "setting" or "try", its key and its number.
struct LessonValue {
    QString kind;  // "setting", "try"
    QString key;
    double value = 0.0;
    bool valid = false;  // the text is a number
};
QList<LessonValue> lessonValues(const QString& html);
// The text of a section (between its <h3> and the next), empty when there is none.
QString lessonSection(const QString& html, const QString& title);
// The lesson's "run until" times from <span class="until">T</span>, in text order.
QList<double> lessonUntil(const QString& html);

}  // namespace elui
