#pragma once
// The keyboard of a typed field (Parameters, Scene and Run docks): a class types a value, then
// wants Space and S to run and step again, not to type into the field.
//
//   Enter   commits the text; when the value is accepted the field lets go of the keyboard (a
//           refused value stays, marked red, to be corrected).
//   Escape  puts back the value in use, clears the red mark, lets go of the keyboard.
//
// "Lets go": the field loses focus and nothing else takes it, so the window's shortcuts (Space,
// S, Shift+S, Home, End) reach their actions.

#include <functional>

#include <QString>

class QLineEdit;

namespace elui {

// commit: validates and applies the field's text; returns whether it was accepted (and leaves
// the red mark on when not). restore: shows the value in use again, unmarked.
void installFieldKeys(QLineEdit* edit, std::function<bool()> commit, std::function<void()> restore);

// The red mark of a refused text (with the refusal as its tooltip), or none (the tooltip given).
void markField(QLineEdit* edit, const QString& error, const QString& normalTip);

}  // namespace elui
