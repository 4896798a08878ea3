#pragma once
// The GUI's start, after its command line is checked (app/gui/command_line.h): the process
// before the application exists (GL format, --help without a display, Qt's start-up messages
// held), then the window the request asks for, in one of its three modes: interactive,
// --measure-fps (prints and exits) and --screenshot (renders, writes the PNG, exits).

#include <QString>

class QApplication;

namespace elgui {

struct GuiRequest;
class GuiCommandLine;

// "elastic-lab: MESSAGE" on stderr; exit status 2 (bad input, as for every refusal).
int fail(const QString& message);

// Before QApplication: the default GL format (QOpenGLWidget discipline) and the offscreen
// platform for --help and --version (a headless build machine runs them for the man page).
void beforeApplication(int argc, char** argv);

// Holds Qt's messages while the application starts (RAII): on a fatal one (no display) a
// single line says what to do and the process exits 2; release() prints the held ones.
class HeldStartupMessages {
public:
    HeldStartupMessages();
    ~HeldStartupMessages();
    HeldStartupMessages(const HeldStartupMessages&) = delete;
    HeldStartupMessages& operator=(const HeldStartupMessages&) = delete;
    void release();

private:
    bool m_held = true;
};

// Names, version, desktop id and icon of the application.
void describeApplication();

// The window's language: --lang, else View > Language's choice (not for screenshots, which keep
// no settings), else the system's. Before any widget or translated text is made.
void applyLanguage(const GuiCommandLine& commandLine);

// Builds the window the request asks for and runs the event loop; returns the exit status.
int runWindow(QApplication& app, const GuiRequest& request);

}  // namespace elgui
