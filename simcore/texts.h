#pragma once
// SIMCORE_TEXT("simcore", text): a text of simcore's tables that the GUI shows - a parameter's
// meaning, a scene's or an integrator's description. It is the text itself (simcore stays free
// of Qt); the GUI's lupdate reads the name as QT_TRANSLATE_NOOP (ui/CMakeLists.txt) and files
// the text under the context "simcore", and the GUI shows it through elui::simcoreText() in the
// chosen language. The CLI, Python and the files keep the English text.
#define SIMCORE_TEXT(context, text) text
