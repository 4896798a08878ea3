#!/usr/bin/env python3
"""Reads Elastic Lab's window as a screen reader does: through AT-SPI (the D-Bus accessibility bus
that Orca listens to), not through Qt. Lists every focusable control with its role, name and
description, and counts those without a name or a description. docs/accessibility.md.

    scripts/atspi-tree.py build/release/app/gui/elastic-lab [ARGS...]

Starts its own D-Bus session, accessibility bus and X server (xvfb-run), so it runs anywhere
(Debian: at-spi2-core, python3-pyatspi, xvfb, dbus). Exit status 1 when a control is unnamed.
"""
import os
import subprocess
import sys
import time

if os.environ.get("ELASTIC_LAB_ATSPI_INNER") != "1":
    # Re-run inside a private X server and D-Bus session with the accessibility bus.
    env = dict(os.environ, ELASTIC_LAB_ATSPI_INNER="1", QT_LINUX_ACCESSIBILITY_ALWAYS_ON="1",
               QT_ACCESSIBILITY="1", NO_AT_BRIDGE="0", QT_QPA_PLATFORM="xcb")
    sys.exit(subprocess.call(["xvfb-run", "-a", "-s", "-screen 0 1280x800x24", "dbus-run-session", "--",
                              sys.executable, *sys.argv], env=env))

import pyatspi  # noqa: E402

launcher = subprocess.Popen(["/usr/libexec/at-spi-bus-launcher", "--launch-immediately"])
time.sleep(1.0)
app = subprocess.Popen(sys.argv[1:])
target = None
deadline = time.time() + 60
while time.time() < deadline and target is None:
    time.sleep(0.5)
    desktop = pyatspi.Registry.getDesktop(0)
    for i in range(desktop.childCount):
        a = desktop.getChildAtIndex(i)
        if a is not None and "elastic" in (a.name or "").lower():
            target = a
if target is None:
    print("elastic-lab did not appear on the accessibility bus")
    app.kill()
    sys.exit(2)
time.sleep(2.0)

unnamed = undescribed = focusable = 0
def walk(node, depth):
    global unnamed, undescribed, focusable
    for i in range(node.childCount):
        child = node.getChildAtIndex(i)
        if child is None:
            continue
        states = child.getState()
        if states.contains(pyatspi.STATE_SHOWING) and states.contains(pyatspi.STATE_FOCUSABLE):
            focusable += 1
            name, desc = (child.name or "").strip(), (child.description or "").strip()
            mark = "NO NAME " if not name else ("no description " if not desc else "")
            unnamed += not name
            undescribed += bool(name) and not desc
            print(f"{'  ' * depth}{mark}[{child.getRoleName()}] {name[:70]!r} - {desc[:70]!r}")
        walk(child, depth + 1)
walk(target, 0)
print(f"focusable controls shown: {focusable}; without a name: {unnamed}; named but without a description: {undescribed}")
app.terminate()
app.wait()
launcher.terminate()
sys.exit(1 if unnamed else 0)
