#pragma once
// The measurement behind every figure a lesson or Help states (ui/lessons.h: <span
// class="answer" data-key=...>), as the elastic-lab-cli command beside it measures it, on any
// parameter set. test_lessons runs them on the lesson's preset (Help: the default ring) and
// compares with the text; the Lesson dock runs them on the parameters in use ("Measure") and
// shows them beside the figures the text expects. One table: a figure cannot be stated in one
// place and measured differently in another.

#include <functional>

#include <QMap>
#include <QString>

#include "simcore/params.h"

namespace elui {

using LessonMeasure = std::function<double(const simcore::ParameterSet&)>;

// The measurements of a lesson's answers by key (empty for an unknown lesson).
QMap<QString, LessonMeasure> lessonMeasures(const QString& lessonId);
// The measurements of a lesson of several bodies (lessonMeasures hands them on): its world as set
// up, with the parameters given applied to the first body (world parameters to every body).
QMap<QString, LessonMeasure> worldLessonMeasures(const QString& lessonId);
// The measurements of the figures in Help (HelpDialog::html()) by key, on the scene they name.
QMap<QString, LessonMeasure> helpMeasures();

// The simulated time a run fails (the start of the failing step), or -1 when it reaches `until`.
double lessonFailureTime(const simcore::ParameterSet& p, const std::string& integrator, double until);
// After the first wall contact, the first time no particle touches a wall (Diagnostics::contact
// is 0: the body is in the air), or -1 when that does not happen before `until`.
double lessonLiftOffTime(const simcore::ParameterSet& p, const std::string& integrator, double until);

}  // namespace elui
