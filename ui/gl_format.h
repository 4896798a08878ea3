#pragma once
// The one OpenGL format of the views (3.3 core, depth, stencil, `samples` x multisampling),
// set as the default before the application exists (QOpenGLWidget discipline): by main() and
// by the tests that draw.

#include <QSurfaceFormat>

namespace elui {

inline void setDefaultGlFormat(int samples = 0) {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setSamples(samples);
    QSurfaceFormat::setDefaultFormat(format);
}

}  // namespace elui
