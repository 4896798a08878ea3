#include "ui/viewport.h"

#include <algorithm>
#include <cmath>

#include <QGuiApplication>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QFrame>
#include <QKeyEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QLabel>
#include <QPainter>
#include <QTextDocument>
#include <QWheelEvent>

#include "ui/failure_text.h"
#include "ui/language.h"
#include "ui/plot_series.h"

static void initElasticLabResources() { Q_INIT_RESOURCE(elastic_lab); }

namespace elui {

namespace {

QString g_renderer;  // GL_RENDERER of the probe context
int g_samples = -1;  // viewports' multisampling, < 0: the default format's

const QVector4D kFamilyColor[3] = {
    {0.12f, 0.14f, 0.22f, 1.0f},  // structural: near black
    {0.10f, 0.55f, 0.25f, 1.0f},  // radius: green
    {0.55f, 0.25f, 0.70f, 1.0f},  // shear: purple
};
const QVector4D kInnerFace{0.30f, 0.50f, 0.95f, 1.0f};
const QVector4D kOuterFace{0.98f, 0.60f, 0.20f, 0.30f};
const QVector4D kInnerFill{0.55f, 0.70f, 1.00f, 0.85f};
const QVector4D kOuterFill{1.00f, 0.75f, 0.45f, 0.75f};
const QVector4D kBoxColor{0.45f, 0.47f, 0.52f, 1.0f};
const QVector4D kFloorColor{0.80f, 0.82f, 0.86f, 1.0f};
const QVector4D kForceColor{0.85f, 0.10f, 0.10f, 1.0f};
const QVector4D kVelocityColor{0.05f, 0.45f, 0.75f, 1.0f};
const QVector4D kRulerColor{0.45f, 0.10f, 0.55f, 1.0f};
const QVector4D kNormalColor{0.10f, 0.55f, 0.60f, 1.0f};
const QVector4D kMouseColor{0.95f, 0.70f, 0.00f, 1.0f};

// A press released within this many pixels of where it went down is a click [px].
constexpr double kClickSlop = 4.0;

// The colour of a force part: the energy colour of the matching term (the energy plot, the
// energy bars), so a term looks the same wherever it is drawn.
QColor forcePartColor(simcore::ForcePart part) {
    using P = simcore::ForcePart;
    switch (part) {
        case P::Gravity: return energyColor(EnergyTerm::Gravity);
        case P::Structural: return energyColor(EnergyTerm::SpringStructural);
        case P::Radius: return energyColor(EnergyTerm::SpringRadius);
        case P::Shear: return energyColor(EnergyTerm::SpringShear);
        case P::GasInner:
        case P::GasOuter: return energyColor(EnergyTerm::Gas);
        case P::Walls: return energyColor(EnergyTerm::Contact);
        case P::Barrier: return energyColor(EnergyTerm::Contact).darker(160);
        case P::Mouse: return energyColor(EnergyTerm::Mouse);
        // A world's pairs: the contact account's hue, lighter for the other bodies, violet for self.
        case P::BodyContact: return energyColor(EnergyTerm::Contact).lighter(150);
        case P::SelfContact: return QColor(140, 60, 170);
        case P::Count: break;
    }
    return Qt::black;
}

QVector4D rgba(const QColor& c) { return {float(c.redF()), float(c.greenF()), float(c.blueF()), 1.0f}; }

std::vector<GLuint> loopFan(const simcore::Surface& surface) {
    // The polygon's vertices in edge order, as a triangle fan around the first one.
    std::vector<GLuint> loop;
    for (const auto& e : surface.edges) loop.push_back(GLuint(e[0]));
    std::vector<GLuint> fan;
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) fan.insert(fan.end(), {loop[0], loop[i], loop[i + 1]});
    return fan;
}

// Particle i of a lane's positions (3N floats).
QVector3D pointOf(const std::vector<float>& x, int i) {
    return QVector3D(x[3 * std::size_t(i)], x[3 * std::size_t(i) + 1], x[3 * std::size_t(i) + 2]);
}

// A triangle list as GL indices.
std::vector<GLuint> triangleIndices(const std::vector<std::array<int, 3>>& tris) {
    std::vector<GLuint> idx;
    for (const auto& t : tris) idx.insert(idx.end(), {GLuint(t[0]), GLuint(t[1]), GLuint(t[2])});
    return idx;
}

}  // namespace

// Colour legend for strain (L - L0) / L0, matching lines.geom's map.
class StrainLegend : public QWidget {
public:
    explicit StrainLegend(QWidget* parent) : QWidget(parent) {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setFixedSize(96, 190);
    }
    void setRange(double range) {
        m_range = range;
        update();
    }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        painter.fillRect(rect(), QColor(255, 255, 255, 215));
        painter.setPen(QColor(160, 160, 170));
        painter.drawRect(rect().adjusted(0, 0, -1, -1));
        const QFontMetrics fm(font());
        const int w = 18, x0 = 10, y0 = fm.height() + 12, h = height() - y0 - 12;
        painter.setPen(QColor(30, 30, 30));
        painter.drawText(x0, fm.ascent() + 5, tr("spring strain"));
        QLinearGradient g(0, y0, 0, y0 + h);
        g.setColorAt(0.0, QColor::fromRgbF(0.9f, 0.12f, 0.1f));
        g.setColorAt(0.5, QColor::fromRgbF(0.95f, 0.95f, 0.95f));
        g.setColorAt(1.0, QColor::fromRgbF(0.15f, 0.35f, 0.95f));
        painter.fillRect(QRect(x0, y0, w, h), g);
        painter.drawRect(QRect(x0, y0, w, h));
        const int pct = int(std::lround(m_range * 100));
        painter.drawText(x0 + w + 6, y0 + fm.ascent() / 2, QStringLiteral("+%1 %").arg(pct));
        painter.drawText(x0 + w + 6, y0 + h / 2 + fm.ascent() / 2, QStringLiteral("0 (rest)"));
        painter.drawText(x0 + w + 6, y0 + h + fm.ascent() / 2 - 2, QStringLiteral("-%1 %").arg(pct));
    }

private:
    double m_range = 0.2;
};

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent) {
    initElasticLabResources();
    if (g_samples >= 0) {
        QSurfaceFormat f = format();
        f.setSamples(g_samples);
        setFormat(f);
    }
    setMinimumSize(150, 150);  // three side by side beside the docks on a 1280 px projector
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    m_info = new QLabel(this);
    m_info->setTextFormat(Qt::RichText);
    m_info->setWordWrap(true);
    m_info->setAlignment(Qt::AlignLeft | Qt::AlignTop);  // a wrapped failure line under the rest, not centred
    m_info->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_info->setStyleSheet(QStringLiteral("QLabel { color: #202030; background: rgba(255,255,255,150); padding: 3px; }"));
    m_info->move(8, 8);
    m_legend = new StrainLegend(this);
    m_legend->hide();
    m_forcesPanel = new QLabel(this);
    m_forcesPanel->setObjectName(QStringLiteral("forcesPanel"));
    m_forcesPanel->setTextFormat(Qt::RichText);
    m_forcesPanel->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_forcesPanel->setStyleSheet(
        QStringLiteral("QLabel { color: #202030; background: rgba(255,255,255,215); border: 1px solid #a0a0aa; padding: 4px; }"));
    m_forcesPanel->hide();
    m_rulerLabel = new QLabel(this);
    m_rulerLabel->setObjectName(QStringLiteral("rulerLabel"));
    m_rulerLabel->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_rulerLabel->setStyleSheet(QStringLiteral("QLabel { background: rgba(255,255,255,220); color: #731a8c; "
                                               "border: 1px solid #731a8c; padding: 2px; }"));
    m_rulerLabel->hide();
    // Keyboard: a visible frame while the view has focus (drawn over the GL image).
    m_focusFrame = new QFrame(this);
    m_focusFrame->setObjectName(QStringLiteral("focusFrame"));
    m_focusFrame->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_focusFrame->hide();
    setHighContrast(false);
    setAccessibleName(tr("Simulation view"));
    setAccessibleDescription(
        tr("The body. Keyboard: arrow keys or Page Up and Page Down choose a particle and show the forces on it; "
           "Enter grabs it with the mouse spring, then the arrow keys drag it (Shift: ten times farther) and "
           "Enter or Escape lets go; Escape clears the choice."));
}

void Viewport::setHighContrast(bool on) {
    m_highContrast = on;
    m_info->setStyleSheet(on ? QStringLiteral("QLabel { color: white; background: black; padding: 3px; }")
                             : QStringLiteral("QLabel { color: #202030; background: rgba(255,255,255,150); padding: 3px; }"));
    m_focusFrame->setStyleSheet(on ? QStringLiteral("QFrame { border: 4px solid yellow; background: transparent; }")
                                   : QStringLiteral("QFrame { border: 3px solid #1a5fd0; background: transparent; }"));
    update();
}

void Viewport::focusInEvent(QFocusEvent* event) {
    QOpenGLWidget::focusInEvent(event);
    m_focusFrame->setGeometry(rect());
    m_focusFrame->show();
    m_focusFrame->raise();
}

void Viewport::focusOutEvent(QFocusEvent* event) {
    QOpenGLWidget::focusOutEvent(event);
    m_focusFrame->hide();
}

QPointF Viewport::pixelOf(int particle) const {
    const auto& x = m_frame->lanes[std::size_t(std::clamp(m_lane, 0, int(m_frame->lanes.size()) - 1))].positions;
    const QVector3D p(x[3 * std::size_t(particle)], x[3 * std::size_t(particle) + 1], x[3 * std::size_t(particle) + 2]);
    const QVector3D ndc = (m_camera.projection(size()) * m_camera.view()).map(p);
    return {(ndc.x() + 1.0) * 0.5 * width(), (1.0 - ndc.y()) * 0.5 * height()};
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    const int count = m_frame && m_frame->scene ? m_frame->scene->topology.particleCount() : 0;
    if (count == 0) return QOpenGLWidget::keyPressEvent(event);
    const int key = event->key();
    const bool enter = key == Qt::Key_Return || key == Qt::Key_Enter;
    if (m_drag == Drag::Grab) {
        // Dragging by keyboard: the anchor moves in the plane facing the camera, 8 pixels a
        // press (Shift: 80); Enter or Escape lets go.
        const double step = event->modifiers() & Qt::ShiftModifier ? 80.0 : 8.0;
        QPointF d;
        if (key == Qt::Key_Left) d = {-step, 0};
        else if (key == Qt::Key_Right) d = {step, 0};
        else if (key == Qt::Key_Up) d = {0, -step};
        else if (key == Qt::Key_Down) d = {0, step};
        else if (enter || key == Qt::Key_Escape) {
            emit releaseRequested();
            m_drag = Drag::None;
            m_grabbed = false;
            return;
        } else {
            return QOpenGLWidget::keyPressEvent(event);
        }
        m_lastPixel += d;
        if (m_grabbed) emit anchorMoved(anchorUnder(m_lastPixel));
        return;
    }
    int next = m_keyboardParticle;
    const int jump = event->modifiers() & Qt::ShiftModifier ? 10 : 1;
    if (key == Qt::Key_Right || key == Qt::Key_Down || key == Qt::Key_PageDown) next = next < 0 ? 0 : (next + jump) % count;
    else if (key == Qt::Key_Left || key == Qt::Key_Up || key == Qt::Key_PageUp)
        next = next < 0 ? count - 1 : ((next - jump) % count + count) % count;
    else if (key == Qt::Key_Escape) next = -1;  // Home and End travel the timeline
    else if (enter && m_keyboardParticle >= 0) {
        // Grab the chosen particle as a press on it would (the worker picks along the ray
        // through it, the nearest outer particle; onGrabbed starts the drag).
        m_lastPixel = pixelOf(m_keyboardParticle);
        const Ray ray = m_camera.rayAt(m_lastPixel, size());
        m_drag = Drag::Grab;
        m_grabbed = false;
        emit grabRequested(ray.origin, ray.direction, 28.0 * m_camera.worldPerPixel(size()));
        return;
    } else {
        return QOpenGLWidget::keyPressEvent(event);
    }
    m_keyboardParticle = next;
    emit particleSelected(next);
}

Viewport::~Viewport() {
    // The context outlives this part of the object (QOpenGLWidget's destructor destroys it):
    // its aboutToBeDestroyed must not call cleanup() on a Viewport that is already gone
    // (found by UBSan: a downcast to a destroyed Viewport).
    if (QOpenGLContext* gl = context()) disconnect(gl, nullptr, this, nullptr);
    makeCurrent();
    cleanup();
    doneCurrent();
}

QString Viewport::rendererName() { return g_renderer; }

bool Viewport::softwareRenderer() {
    return g_renderer.contains(QLatin1String("llvmpipe")) || g_renderer.contains(QLatin1String("softpipe")) ||
           g_renderer.contains(QLatin1String("swrast"));
}

void Viewport::setSamples(int samples) { g_samples = samples; }

bool Viewport::openGLAvailable() {
    static int cached = -1;
    if (cached >= 0) return cached == 1;
    cached = 0;
    const QString platform = QGuiApplication::platformName();
    if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal")) return false;
    QOpenGLContext context;
    context.setFormat(QSurfaceFormat::defaultFormat());
    if (!context.create()) return false;
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    if (!context.makeCurrent(&surface)) return false;
    const auto version = context.format().version();
    cached = version >= qMakePair(3, 3) ? 1 : 0;
    if (const auto* name = context.functions()->glGetString(GL_RENDERER))
        g_renderer = QString::fromLatin1(reinterpret_cast<const char*>(name));
    context.doneCurrent();
    return cached == 1;
}

void Viewport::setOptions(const ViewOptions& options) {
    m_options = options;
    updateOverlay();
    m_legend->setVisible(options.strain);
    updateRulerLabel();
    update();
}

void Viewport::setCamera(const Camera& camera) {
    if (m_camera == camera) return;
    m_camera = camera;
    update();
}

void Viewport::resetView() {
    m_camera.resetView();
    emit cameraChanged(m_camera);
    update();
}

void Viewport::showFrame(const FramePtr& frame) {
    if (!frame || frame->lanes.empty()) return;
    const bool newScene = !m_frame || m_frame->scene != frame->scene;
    if (newScene) {
        const SceneData& s = *frame->scene;
        const bool sameKind = m_frame && m_frame->scene->kind == s.kind &&
                              std::abs(m_frame->scene->bodyRadius - s.bodyRadius) < 0.1 * s.bodyRadius;
        m_camera.setMode2d(s.topology.dimension < 3);
        if (!sameKind) {
            const Eigen::Vector3d& c = s.boxCentre;
            m_camera.fit(QVector3D(float(c.x()), float(c.y()), float(c.z())), float(s.bodyRadius),
                         float(s.boxHalfSize));
        }
    }
    m_frame = frame;
    // The text over the view (time, distance, failure) is rich text laid out anew whenever it
    // changes: while running, ten times a second is readable and spares the GUI thread a
    // layout per frame; a paused, stepped or failed frame shows at once.
    const bool failed = std::any_of(frame->lanes.begin(), frame->lanes.end(), [](const LaneFrame& l) { return l.failure.has_value(); });
    if (!frame->running || failed || newScene || !m_overlayClock.isValid() || m_overlayClock.elapsed() >= 100) {
        m_overlayClock.start();
        updateOverlay();
    }
    update();
}

void Viewport::initializeGL() {
    initializeOpenGLFunctions();
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::cleanup, Qt::UniqueConnection);

    auto build = [](std::initializer_list<std::pair<QOpenGLShader::ShaderType, const char*>> stages) {
        auto program = std::make_unique<QOpenGLShaderProgram>();
        for (const auto& [type, file] : stages)
            if (!program->addShaderFromSourceFile(type, QString::fromLatin1(file)))
                qWarning("shader %s: %s", file, qPrintable(program->log()));
        if (!program->link()) qWarning("link: %s", qPrintable(program->log()));
        return program;
    };
    using S = QOpenGLShader;
    m_lines = build({{S::Vertex, ":/shaders/lines.vert"}, {S::Geometry, ":/shaders/lines.geom"},
                     {S::Fragment, ":/shaders/color.frag"}});
    m_normals = build({{S::Vertex, ":/shaders/lines.vert"}, {S::Geometry, ":/shaders/normals.geom"},
                       {S::Fragment, ":/shaders/color.frag"}});
    m_surface = build({{S::Vertex, ":/shaders/lines.vert"}, {S::Fragment, ":/shaders/surface.frag"}});
    m_points = build({{S::Vertex, ":/shaders/points.vert"}, {S::Fragment, ":/shaders/points.frag"}});

    m_vao.create();
    m_positions.create();
    m_positions.setUsagePattern(QOpenGLBuffer::StreamDraw);
    m_layers.create();
    m_scratchVao.create();
    m_scratch.create();
    m_scratch.setUsagePattern(QOpenGLBuffer::StreamDraw);
    for (auto& s : m_springs) s.buffer.create();
    for (Elements* e : {&m_innerFaces, &m_outerFaces, &m_fill, &m_innerFan, &m_outerFan}) e->buffer.create();
    glGenBuffers(3, m_restBuffers.data());
    glGenTextures(3, m_restTextures.data());

    m_scratchVao.bind();
    m_scratch.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    m_scratchVao.release();

    m_uploadedScene.reset();  // a new context needs everything again
    m_glReady = true;
}

void Viewport::cleanup() {
    if (!m_glReady) return;
    makeCurrent();
    m_lines.reset();
    m_normals.reset();
    m_surface.reset();
    m_points.reset();
    m_vao.destroy();
    m_scratchVao.destroy();
    m_positions.destroy();
    m_layers.destroy();
    m_scratch.destroy();
    for (auto& s : m_springs) s.buffer.destroy();
    for (Elements* e : {&m_innerFaces, &m_outerFaces, &m_fill, &m_innerFan, &m_outerFan}) e->buffer.destroy();
    releaseBodyFaces();
    glDeleteTextures(3, m_restTextures.data());
    glDeleteBuffers(3, m_restBuffers.data());
    m_uploadedScene.reset();
    m_glReady = false;
    doneCurrent();
}

void Viewport::resizeGL(int, int) {}

void Viewport::uploadIndices(Elements& e, const std::vector<GLuint>& indices) {
    e.buffer.bind();
    e.buffer.allocate(indices.data(), int(indices.size() * sizeof(GLuint)));
    e.count = int(indices.size());
}

void Viewport::uploadScene() {
    const SceneData& scene = *m_frame->scene;
    const simcore::Topology& topo = scene.topology;
    m_particleCount = topo.particleCount();

    m_vao.bind();
    m_positions.bind();
    m_positions.allocate(int(sizeof(float)) * 3 * m_particleCount);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    const std::vector<float> layer = particleCodes(scene);
    m_layers.bind();
    m_layers.allocate(layer.data(), int(layer.size() * sizeof(float)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 0, nullptr);

    uploadSprings(topo);
    // Every surface of a layer together (a world has one per body and layer).
    std::array<std::vector<GLuint>, 2> faces, fans;
    for (const simcore::Surface& s : topo.surfaces) {
        const auto slot = std::size_t(s.layer == simcore::Layer::Inner ? 0 : 1);
        const std::vector<GLuint> t = triangleIndices(s.triangles);
        faces[slot].insert(faces[slot].end(), t.begin(), t.end());
        if (!s.edges.empty()) {
            const std::vector<GLuint> fan = loopFan(s);
            fans[slot].insert(fans[slot].end(), fan.begin(), fan.end());
        }
    }
    uploadIndices(m_innerFaces, faces[0]);
    uploadIndices(m_outerFaces, faces[1]);
    uploadIndices(m_innerFan, fans[0]);
    uploadIndices(m_outerFan, fans[1]);
    uploadIndices(m_fill, triangleIndices(topo.fillTriangles));
    uploadBodyFaces(scene);
    m_vao.release();
    m_uploadedScene = m_frame->scene;
}

void Viewport::uploadSprings(const simcore::Topology& topo) {
    // Each family's index pairs, and its rest lengths as a buffer texture (strain colours).
    for (int f = 0; f < 3; ++f) {
        const simcore::SpringSet& set = topo.springs[std::size_t(f)];
        std::vector<GLuint> idx;
        std::vector<float> rest;
        for (std::size_t s = 0; s < set.size(); ++s) {
            idx.push_back(GLuint(set.a[s]));
            idx.push_back(GLuint(set.b[s]));
            rest.push_back(float(set.rest[s]));
        }
        uploadIndices(m_springs[std::size_t(f)], idx);
        if (rest.empty()) rest.push_back(1.0f);
        glBindBuffer(GL_TEXTURE_BUFFER, m_restBuffers[std::size_t(f)]);
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(rest.size() * sizeof(float)), rest.data(), GL_STATIC_DRAW);
        glBindTexture(GL_TEXTURE_BUFFER, m_restTextures[std::size_t(f)]);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_R32F, m_restBuffers[std::size_t(f)]);
    }
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
}

std::vector<float> Viewport::particleCodes(const SceneData& scene) {
    const simcore::Topology& topo = scene.topology;
    std::vector<float> code(static_cast<std::size_t>(topo.particleCount()));
    for (std::size_t i = 0; i < code.size(); ++i) code[i] = float(topo.layer[i]);
    // A world's particles in their body's hue: the layer plus 4 (k + 1) for body k.
    for (std::size_t k = 0; k < scene.bodies.size(); ++k)
        for (int i = scene.bodies[k].first; i < scene.bodies[k].first + scene.bodies[k].count; ++i)
            code[std::size_t(i)] += float(4 * (k + 1));
    return code;
}

void Viewport::uploadBodyFaces(const SceneData& scene) {
    // Each body's own: the outer faces in 3D, the ring between the layers in 2D.
    const simcore::Topology& topo = scene.topology;
    releaseBodyFaces();
    m_bodyFaces.resize(scene.bodies.size());
    for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
        const auto& b = scene.bodies[k];
        const auto inside = [&](const std::array<int, 3>& t) { return t[0] >= b.first && t[0] < b.first + b.count; };
        std::vector<std::array<int, 3>> own;
        for (const auto& t : topo.fillTriangles)
            if (inside(t)) own.push_back(t);
        for (const simcore::Surface& s : topo.surfaces)
            if (s.layer == simcore::Layer::Outer)
                for (const auto& t : s.triangles)
                    if (inside(t)) own.push_back(t);
        m_bodyFaces[k].buffer.create();
        uploadIndices(m_bodyFaces[k], triangleIndices(own));
    }
}

void Viewport::releaseBodyFaces() {
    for (Elements& e : m_bodyFaces) e.buffer.destroy();
    m_bodyFaces.clear();
}

void Viewport::uploadPositions(const LaneFrame& lane) {
    m_positions.bind();
    m_positions.write(0, lane.positions.data(), int(lane.positions.size() * sizeof(float)));
}

void Viewport::drawElementsLines(const Elements& e, const QVector4D& color, float width, int family) {
    if (e.count == 0) return;
    m_lines->bind();
    m_lines->setUniformValue("uColor", color);
    m_lines->setUniformValue("uWidth", width * float(devicePixelRatioF()));
    const bool strain = family >= 0 && m_options.strain;
    m_lines->setUniformValue("uStrainMode", strain ? 1 : 0);
    if (strain) {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_BUFFER, m_restTextures[std::size_t(family)]);
        m_lines->setUniformValue("uRest", 0);
        m_lines->setUniformValue("uStrainRange", float(m_options.strainRange));
    }
    m_vao.bind();
    e.buffer.bind();
    glDrawElements(GL_LINES, e.count, GL_UNSIGNED_INT, nullptr);
}

void Viewport::drawSegments(const std::vector<float>& xyz, const QVector4D& color, float width) {
    if (xyz.size() < 6) return;
    m_scratchVao.bind();
    m_scratch.bind();
    m_scratch.allocate(xyz.data(), int(xyz.size() * sizeof(float)));
    m_lines->bind();
    m_lines->setUniformValue("uColor", color);
    m_lines->setUniformValue("uWidth", width * float(devicePixelRatioF()));
    m_lines->setUniformValue("uStrainMode", 0);
    glDrawArrays(GL_LINES, 0, GLsizei(xyz.size() / 3));
    m_scratchVao.release();
}

void Viewport::drawSurface(const Elements& e, const QVector4D& color, bool lit) {
    if (e.count == 0) return;
    m_surface->bind();
    m_surface->setUniformValue("uColor", color);
    m_surface->setUniformValue("uLit", lit ? 1 : 0);
    m_vao.bind();
    e.buffer.bind();
    glDrawElements(GL_TRIANGLES, e.count, GL_UNSIGNED_INT, nullptr);
}

void Viewport::drawPolygonStencil(const Elements& fan, const QVector4D& color) {
    // Even-odd fill of a simple polygon of any shape: every fan triangle inverts the stencil;
    // pixels covered an odd number of times are inside.
    if (fan.count == 0) return;
    glEnable(GL_STENCIL_TEST);
    glClear(GL_STENCIL_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
    drawSurface(fan, color, false);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_NOTEQUAL, 0, 0xff);
    glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
    drawSurface(fan, color, false);
    glDisable(GL_STENCIL_TEST);
}

void Viewport::drawBox() {
    const SceneData& s = *m_frame->scene;
    const float h = float(s.boxHalfSize);
    const QVector3D c(float(s.boxCentre.x()), float(s.boxCentre.y()), float(s.boxCentre.z()));
    std::vector<float> v;
    v.reserve(6 * 28);
    auto seg = [&](QVector3D a, QVector3D b) {
        a = c + a * h;
        b = c + b * h;
        for (float f : {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}) v.push_back(f);
    };
    if (m_camera.is2d()) {
        seg({-1, -1, 0}, {1, -1, 0});
        seg({1, -1, 0}, {1, 1, 0});
        seg({1, 1, 0}, {-1, 1, 0});
        seg({-1, 1, 0}, {-1, -1, 0});
        drawSegments(v, kBoxColor, 2.0f);
        v.clear();
        seg({-1, -1, 0}, {1, -1, 0});
        drawSegments(v, {0.25f, 0.25f, 0.3f, 1.0f}, 5.0f);  // the floor
        return;
    }
    for (int i = 0; i < 4; ++i) {
        const float x0 = (i & 1) ? 1.f : -1.f, z0 = (i & 2) ? 1.f : -1.f;
        seg({x0, -1, z0}, {x0, 1, z0});  // vertical edges
    }
    for (float y : {-1.f, 1.f}) {
        seg({-1, y, -1}, {1, y, -1});
        seg({-1, y, 1}, {1, y, 1});
        seg({-1, y, -1}, {-1, y, 1});
        seg({1, y, -1}, {1, y, 1});
    }
    drawSegments(v, kBoxColor, 1.5f);
    // The floor as a filled quad, with a light grid.
    std::vector<float> quad;
    for (auto [x, z] : {std::pair{-1.f, -1.f}, {1.f, -1.f}, {1.f, 1.f}, {-1.f, -1.f}, {1.f, 1.f}, {-1.f, 1.f}}) {
        const QVector3D p = c + QVector3D(x, -1.0f, z) * h;
        quad.insert(quad.end(), {p.x(), p.y() - 0.002f * h, p.z()});
    }
    m_scratchVao.bind();
    m_scratch.bind();
    m_scratch.allocate(quad.data(), int(quad.size() * sizeof(float)));
    m_surface->bind();
    m_surface->setUniformValue("uColor", kFloorColor);
    m_surface->setUniformValue("uLit", 0);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    m_scratchVao.release();
    v.clear();
    for (int i = 1; i < 8; ++i) {
        const float t = -1.0f + 2.0f * float(i) / 8.0f;
        seg({t, -1, -1}, {t, -1, 1});
        seg({-1, -1, t}, {1, -1, t});
    }
    drawSegments(v, {0.68f, 0.70f, 0.75f, 1.0f}, 1.0f);
}

void Viewport::paintGL() {
    ++m_paints;
    if (m_highContrast) glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    else glClearColor(0.95f, 0.96f, 0.975f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (!m_frame || !m_lines || !m_lines->isLinked()) return;
    const int laneIndex = std::clamp(m_lane, 0, int(m_frame->lanes.size()) - 1);
    const LaneFrame& lane = m_frame->lanes[std::size_t(laneIndex)];
    if (m_uploadedScene != m_frame->scene) uploadScene();
    uploadPositions(lane);

    const QSize pixels = size() * devicePixelRatioF();
    const QMatrix4x4 mvp = m_camera.projection(size()) * m_camera.view();
    const QVector2D viewport(float(pixels.width()), float(pixels.height()));
    for (QOpenGLShaderProgram* p : {m_lines.get(), m_normals.get(), m_surface.get(), m_points.get()}) {
        p->bind();
        p->setUniformValue("uMVP", mvp);
        p->setUniformValue("uViewport", viewport);
        p->setUniformValue("uEye", m_camera.eye());
    }
    glEnable(GL_BLEND);
    // Keep destination alpha at 1: the widget's image is composited as premultiplied ARGB.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_PROGRAM_POINT_SIZE);

    const SceneData& scene = *m_frame->scene;
    const bool flat = m_camera.is2d();
    const float lineWidth = flat ? 2.5f : 1.6f;
    const auto& x = lane.positions;

    if (flat) glDisable(GL_DEPTH_TEST);
    else glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    if (m_options.box) drawBox();

    if (m_options.faces) drawInnerFaces(scene, flat);
    for (int f = 0; f < 3; ++f)
        if (m_options.springs[f])
            drawElementsLines(m_springs[std::size_t(f)],
                              m_highContrast && f == 0 ? QVector4D(1.0f, 1.0f, 1.0f, 1.0f) : kFamilyColor[f],
                              f == 0 ? lineWidth * 1.3f : lineWidth, f);
    if (m_options.normals) drawNormals(scene, lane, flat);

    if (m_options.particles && m_particleCount > 0) {
        m_points->bind();
        const float size = flat ? 11.0f : (m_particleCount > 600 ? 5.0f : 8.0f);
        m_points->setUniformValue("uSize", size * float(devicePixelRatioF()));
        m_points->setUniformValue("uGrabbed", lane.pointer.active ? lane.pointer.particle : -1);
        std::array<QVector3D, 8> hues;
        for (int k = 0; k < 8; ++k) hues[std::size_t(k)] = rgba(bodyColor(k)).toVector3D();
        m_points->setUniformValueArray("uBodyHue", hues.data(), 8);
        m_vao.bind();
        glDrawArrays(GL_POINTS, 0, m_particleCount);
    }

    if (m_options.forces && lane.forces.size() == x.size()) drawArrows(x, lane.forces, kForceColor);
    if (m_options.velocities && lane.velocities.size() == x.size()) drawArrows(x, lane.velocities, kVelocityColor);

    drawForceBreakdown(lane);
    drawRuler();
    if (lane.pointer.active && lane.pointer.particle >= 0 && lane.pointer.particle < m_particleCount)
        drawPointer(lane, flat);
    if (m_options.faces && !flat && m_outerFaces.count > 0) drawOuterFaces(scene);
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
}

void Viewport::drawInnerFaces(const SceneData& scene, bool flat) {
    // In 2D the fill between the layers (each body in its hue in a world) and the inner layer's
    // polygon; in 3D the inner layer's faces (the outer ones are drawn last, translucent).
    if (flat && scene.isWorld()) {
        for (std::size_t k = 0; k < m_bodyFaces.size(); ++k) {
            QVector4D hue = rgba(bodyColor(int(k)));
            hue.setW(kOuterFill.w());
            drawSurface(m_bodyFaces[k], hue, false);
        }
        drawPolygonStencil(m_innerFan, kInnerFill);
    } else if (flat) {
        drawSurface(m_fill, kOuterFill, false);
        drawPolygonStencil(m_innerFan, kInnerFill);
    } else {
        drawSurface(m_innerFaces, kInnerFace, true);
    }
}

void Viewport::drawNormals(const SceneData& scene, const LaneFrame& lane, bool flat) {
    // 2D: a segment from each outer edge's middle; 3D: the normals shader over the outer faces.
    if (flat) {
        std::vector<float> v;
        const simcore::Surface* outer = scene.topology.surface(simcore::Layer::Outer);
        if (outer) {
            const float len = 0.25f * float(scene.bodyRadius);
            for (const auto& e : outer->edges) {
                const QVector3D a = pointOf(lane.positions, e[0]), b = pointOf(lane.positions, e[1]);
                const QVector3D m = 0.5f * (a + b), d = b - a;
                const QVector3D n = QVector3D(d.y(), -d.x(), 0).normalized();  // interior on the left
                const QVector3D tip = m + n * len;
                v.insert(v.end(), {m.x(), m.y(), m.z(), tip.x(), tip.y(), tip.z()});
            }
        }
        drawSegments(v, kNormalColor, 2.0f);
    } else if (m_outerFaces.count > 0) {
        m_normals->bind();
        m_normals->setUniformValue("uColor", kNormalColor);
        m_normals->setUniformValue("uWidth", 1.5f * float(devicePixelRatioF()));
        m_normals->setUniformValue("uLength", 0.2f * float(scene.bodyRadius));
        m_vao.bind();
        m_outerFaces.buffer.bind();
        glDrawElements(GL_TRIANGLES, m_outerFaces.count, GL_UNSIGNED_INT, nullptr);
    }
}

void Viewport::drawPointer(const LaneFrame& lane, bool flat) {
    // The mouse spring from the held particle to its anchor, and a cross at the anchor.
    const QVector3D p = pointOf(lane.positions, lane.pointer.particle);
    const auto& a = lane.pointer.anchor;
    const std::vector<float> v = {p.x(), p.y(), p.z(), float(a.x()), float(a.y()), float(a.z())};
    glDisable(GL_DEPTH_TEST);
    drawSegments(v, kMouseColor, 3.0f);
    const float r = 6.0f * m_camera.worldPerPixel(size());
    const QVector3D ac(float(a.x()), float(a.y()), float(a.z()));
    drawSegments({ac.x() - r, ac.y(), ac.z(), ac.x() + r, ac.y(), ac.z(), ac.x(), ac.y() - r, ac.z(), ac.x(),
                  ac.y() + r, ac.z()},
                 {0.2f, 0.2f, 0.2f, 1.0f}, 2.0f);
    if (!flat) glEnable(GL_DEPTH_TEST);
}

void Viewport::drawOuterFaces(const SceneData& scene) {
    // The outer layer last and translucent: back faces first, then front faces.
    glDepthMask(GL_FALSE);
    glEnable(GL_CULL_FACE);
    const auto outer = [&] {
        if (!scene.isWorld()) {
            drawSurface(m_outerFaces, kOuterFace, true);
            return;
        }
        for (std::size_t k = 0; k < m_bodyFaces.size(); ++k) {
            QVector4D hue = rgba(bodyColor(int(k)));
            hue.setW(kOuterFace.w() + 0.15f);
            drawSurface(m_bodyFaces[k], hue, true);
        }
    };
    glCullFace(GL_FRONT);
    outer();
    glCullFace(GL_BACK);
    outer();
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
}

void Viewport::drawArrows(const std::vector<float>& x, const std::vector<float>& vectors, const QVector4D& color) {
    // Scale so that the 90th-percentile vector is 0.4 body radii long: a few large ones (contact
    // forces, a particle flung away) must not shrink every other arrow to nothing.
    std::vector<double> magnitude;
    for (std::size_t i = 0; i + 2 < vectors.size(); i += 3)
        magnitude.push_back(std::hypot(double(vectors[i]), double(vectors[i + 1]), double(vectors[i + 2])));
    double largest = 0.0;
    if (!magnitude.empty()) {
        auto nth = magnitude.begin() + std::ptrdiff_t(0.9 * double(magnitude.size() - 1));
        std::nth_element(magnitude.begin(), nth, magnitude.end());
        largest = *nth / 0.66;
    }
    if (largest <= 0.0) return;
    const float scale = float(0.6 * m_frame->scene->bodyRadius / largest);
    std::vector<float> v;
    for (std::size_t i = 0; i + 2 < x.size(); i += 3)
        v.insert(v.end(), {x[i], x[i + 1], x[i + 2], x[i] + scale * vectors[i], x[i + 1] + scale * vectors[i + 1],
                           x[i + 2] + scale * vectors[i + 2]});
    drawSegments(v, color, 2.0f);
}

void Viewport::drawRuler() {
    if (!m_options.ruler || !m_hasRuler) return;
    // The line, and a tick across each end (in the view's plane).
    const QVector3D d = m_rulerB - m_rulerA;
    QVector3D across = QVector3D::crossProduct(d, m_camera.forward());
    const float tick = 7.0f * m_camera.worldPerPixel(size());
    across = across.length() > 0 ? across.normalized() * tick : QVector3D(0, tick, 0);
    const QVector3D a1 = m_rulerA - across, a2 = m_rulerA + across, b1 = m_rulerB - across, b2 = m_rulerB + across;
    glDisable(GL_DEPTH_TEST);
    drawSegments({m_rulerA.x(), m_rulerA.y(), m_rulerA.z(), m_rulerB.x(), m_rulerB.y(), m_rulerB.z(), a1.x(), a1.y(),
                  a1.z(), a2.x(), a2.y(), a2.z(), b1.x(), b1.y(), b1.z(), b2.x(), b2.y(), b2.z()},
                 kRulerColor, 2.5f);
    if (!m_camera.is2d()) glEnable(GL_DEPTH_TEST);
}

double Viewport::rulerLength() const { return m_hasRuler ? double((m_rulerB - m_rulerA).length()) : 0.0; }

QString Viewport::rulerText() const { return m_rulerLabel && m_rulerLabel->isVisible() ? m_rulerLabel->text() : QString(); }

void Viewport::updateRulerLabel() {
    if (!m_rulerLabel) return;
    if (!m_options.ruler || !m_hasRuler) {
        m_rulerLabel->hide();
        return;
    }
    const QVector3D d = m_rulerB - m_rulerA;
    QString text = tr("%1 m").arg(num(double(d.length()), 'f', 3));
    if (m_camera.is2d()) text += tr(" (Δx %1, Δy %2)").arg(num(double(d.x()), 'f', 3)).arg(num(double(d.y()), 'f', 3));
    m_rulerLabel->setText(text);
    m_rulerLabel->adjustSize();
    const QPointF p = toPixel(m_rulerB);
    m_rulerLabel->move(std::clamp(int(p.x()) + 10, 0, std::max(0, width() - m_rulerLabel->width())),
                       std::clamp(int(p.y()) - m_rulerLabel->height() - 6, 0, std::max(0, height() - m_rulerLabel->height())));
    m_rulerLabel->show();
}

QPointF Viewport::toPixel(const QVector3D& point) const {
    const QMatrix4x4 mvp = m_camera.projection(size()) * m_camera.view();
    const QVector3D ndc = mvp.map(point);
    return {(ndc.x() + 1.0f) * 0.5f * float(width()), (1.0f - ndc.y()) * 0.5f * float(height())};
}

QVector3D Viewport::onViewPlane(const QPointF& pixel) const {
    // The plane through the box centre facing the camera (in 2D: the body's plane z = 0).
    const QVector3D centre = m_frame && m_frame->scene ? QVector3D(float(m_frame->scene->boxCentre.x()),
                                                                   float(m_frame->scene->boxCentre.y()),
                                                                   float(m_frame->scene->boxCentre.z()))
                                                       : QVector3D();
    const Ray ray = m_camera.rayAt(pixel, size());
    const QVector3D normal = m_camera.forward();
    const float denom = QVector3D::dotProduct(ray.direction, normal);
    if (std::abs(denom) < 1e-6f) return centre;
    return ray.origin + QVector3D::dotProduct(centre - ray.origin, normal) / denom * ray.direction;
}

int Viewport::particleAt(const QPointF& pixel) const {
    if (!m_frame) return -1;
    const auto& x = m_frame->lanes[std::size_t(std::clamp(m_lane, 0, int(m_frame->lanes.size()) - 1))].positions;
    int best = -1;
    double bestDistance = 28.0;
    for (std::size_t i = 0; 3 * i + 2 < x.size(); ++i) {
        const double distance = QLineF(toPixel(QVector3D(x[3 * i], x[3 * i + 1], x[3 * i + 2])), pixel).length();
        if (distance < bestDistance) {
            bestDistance = distance;
            best = int(i);
        }
    }
    return best;
}

void Viewport::drawForceBreakdown(const LaneFrame& lane) {
    if (!lane.breakdown || m_arrowScale <= 0.0) return;
    const simcore::ForceBreakdown& b = *lane.breakdown;
    if (b.particle < 0 || b.particle >= m_particleCount) return;
    const auto i = 3 * std::size_t(b.particle);
    const QVector3D from(lane.positions[i], lane.positions[i + 1], lane.positions[i + 2]);
    const float pixel = m_camera.worldPerPixel(size());
    const QVector3D forward = m_camera.forward();
    // An arrow: the shaft and a head of two strokes in the plane facing the camera.
    auto arrow = [&](const Eigen::Vector3d& force, const QColor& color, float width) {
        const QVector3D d = float(m_arrowScale) * QVector3D(float(force.x()), float(force.y()), float(force.z()));
        const float length = d.length();
        if (length < 2.0f * pixel) return;  // shorter than two pixels: nothing to see
        const QVector3D tip = from + d, dir = d / length;
        QVector3D side = QVector3D::crossProduct(dir, forward);
        if (side.lengthSquared() < 1e-8f) side = QVector3D::crossProduct(dir, QVector3D(0, 0, 1));
        side.normalize();
        const float head = std::min(0.3f * length, 14.0f * pixel);
        const QVector3D back = tip - head * dir, left = back + 0.5f * head * side, right = back - 0.5f * head * side;
        drawSegments({from.x(), from.y(), from.z(), tip.x(), tip.y(), tip.z(), tip.x(), tip.y(), tip.z(), left.x(),
                      left.y(), left.z(), tip.x(), tip.y(), tip.z(), right.x(), right.y(), right.z()},
                     rgba(color), width);
    };
    glDisable(GL_DEPTH_TEST);
    for (int k = 0; k < simcore::kForcePartCount; ++k)
        if (b.present[std::size_t(k)]) arrow(b.part[std::size_t(k)], forcePartColor(simcore::ForcePart(k)), 3.0f);
    arrow(b.total, energyColor(EnergyTerm::Total), 4.0f);
    // The selected particle: a ring of eight strokes around it.
    std::vector<float> ring;
    const QVector3D up = QVector3D::crossProduct(forward, QVector3D::crossProduct(QVector3D(0, 1, 0), forward)).normalized();
    QVector3D across = QVector3D::crossProduct(forward, up).normalized();
    if (!std::isfinite(across.x())) across = QVector3D(1, 0, 0);
    const QVector3D upward = std::isfinite(up.x()) ? up : QVector3D(0, 1, 0);
    const float r = 9.0f * pixel;
    for (int s = 0; s < 16; ++s) {
        const float a0 = float(s) * 0.3927f, a1 = float(s + 1) * 0.3927f;
        const QVector3D p0 = from + r * (std::cos(a0) * across + std::sin(a0) * upward);
        const QVector3D p1 = from + r * (std::cos(a1) * across + std::sin(a1) * upward);
        ring.insert(ring.end(), {p0.x(), p0.y(), p0.z(), p1.x(), p1.y(), p1.z()});
    }
    drawSegments(ring, {0.1f, 0.1f, 0.1f, 1.0f}, 2.0f);
    if (!m_camera.is2d()) glEnable(GL_DEPTH_TEST);
}

void Viewport::updateForcesPanel(const LaneFrame& lane) {
    if (!lane.breakdown || lane.breakdown->particle < 0 || !m_frame) {
        m_arrowScale = 0.0;
        m_forcesPanel->hide();
        return;
    }
    const simcore::ForceBreakdown& b = *lane.breakdown;
    // Scale: the longest arrow (a part or the total) is 0.6 body radii.
    double largest = b.total.norm();
    for (int k = 0; k < simcore::kForcePartCount; ++k) largest = std::max(largest, b.part[std::size_t(k)].norm());
    const double radius = m_frame->scene->bodyRadius;
    m_arrowScale = largest > 0.0 ? 0.6 * radius / largest : 0.0;
    const auto& layers = m_frame->scene->topology.layer;
    const QString layer = std::size_t(b.particle) < layers.size()
                              ? QString::fromUtf8(simcore::layerName(layers[std::size_t(b.particle)]).data())
                              : QString();
    // In a world: which body, and the particle as that body numbers it.
    QString title = tr("Forces on particle %1").arg(b.particle);
    for (std::size_t k = 0; k < m_frame->scene->bodies.size(); ++k) {
        const SceneData::BodySlice& s = m_frame->scene->bodies[k];
        if (b.particle >= s.first && b.particle < s.first + s.count)
            title = tr("Forces on particle %1 of body %2").arg(b.particle - s.first).arg(k + 1);
    }
    QString html = QStringLiteral("<b>%1</b> %2<table cellspacing='0' cellpadding='1'>")
                       .arg(title, layer.isEmpty() ? QString() : QStringLiteral("(%1)").arg(layer));
    auto row = [&](const QColor& c, const QString& name, double newtons, bool bold) {
        const QString value = num(newtons, 'g', 4);
        html += QStringLiteral("<tr><td><span style='color:%1; font-size:large'>&#9632;</span></td><td>%2</td>"
                               "<td align='right'>&nbsp;%3 N</td></tr>")
                    .arg(c.name(), bold ? QStringLiteral("<b>%1</b>").arg(name) : name,
                         bold ? QStringLiteral("<b>%1</b>").arg(value) : value);
    };
    for (int k = 0; k < simcore::kForcePartCount; ++k) {
        if (!b.present[std::size_t(k)]) continue;
        const auto part = simcore::ForcePart(k);
        // A layer's gas acts only on its own particles: the other layer's row says nothing.
        const bool inner = layers.size() > std::size_t(b.particle) && layers[std::size_t(b.particle)] == simcore::Layer::Inner;
        if ((part == simcore::ForcePart::GasInner && !inner) || (part == simcore::ForcePart::GasOuter && inner)) continue;
        const std::string_view name = simcore::forcePartName(part);
        row(forcePartColor(part), QString::fromUtf8(name.data(), qsizetype(name.size())), b.part[std::size_t(k)].norm(), false);
    }
    row(energyColor(EnergyTerm::Total), tr("total (sum)"), b.total.norm(), true);
    html += QStringLiteral("</table>");
    if (m_arrowScale > 0.0)
        html += QStringLiteral("<small>%1</small>").arg(tr("arrows: 1 m = %1 N").arg(1.0 / m_arrowScale, 0, 'g', 3));
    html += QStringLiteral("<br><small>%1</small>").arg(tr("click elsewhere to clear"));
    if (m_forcesPanel->text() != html) {
        m_forcesPanel->setText(html);
        m_forcesPanel->adjustSize();
    }
    m_forcesPanel->move(width() - m_forcesPanel->width() - 8, 8);
    m_forcesPanel->show();
}

void Viewport::resizeEventFrame() { if (m_focusFrame) m_focusFrame->setGeometry(rect()); }

void Viewport::resizeEvent(QResizeEvent* event) {
    resizeEventFrame();
    QOpenGLWidget::resizeEvent(event);
    if (m_forcesPanel) m_forcesPanel->move(width() - m_forcesPanel->width() - 8, 8);
    if (m_legend) m_legend->move(width() - m_legend->width() - 10, height() - m_legend->height() - 10);
    layoutInfo();
}

void Viewport::layoutInfo() {
    if (!m_info) return;
    // As wide as the text's longest line needs (a word-wrapping label's size hint is not
    // that), at most the view's width; tall enough for the wrapped lines.
    QTextDocument document;
    document.setDefaultFont(m_info->font());
    document.setHtml(m_info->text());
    const int padding = 2 * 3 + 2 * m_info->margin() + m_info->contentsMargins().left() +
                        m_info->contentsMargins().right() + 4;  // style sheet padding: 3px
    const int natural = int(std::ceil(document.idealWidth())) + padding;
    const int widest = std::max(120, width() - 16);
    m_info->setFixedWidth(std::clamp(natural, 40, widest));
    const int height = m_info->heightForWidth(m_info->width());
    m_info->setFixedHeight(height > 0 ? height : m_info->sizeHint().height());
}

QString Viewport::overlayText() const { return m_info->text(); }

void Viewport::updateOverlay() {
    if (!m_frame) return;
    const LaneFrame& lane = m_frame->lanes[std::size_t(std::clamp(m_lane, 0, int(m_frame->lanes.size()) - 1))];
    QString html;
    if (!m_title.isEmpty()) html += QStringLiteral("<b>%1</b><br>").arg(m_title.toHtmlEscaped());
    html += QStringLiteral("t = %1 s").arg(num(lane.diagnostics.time, 'f', 3));
    // A world side by side: each view's own total momentum and min_gap (one view: the Bodies dock).
    if (lane.world && m_frame->lanes.size() > 1) {
        const Eigen::Vector3d& p = lane.world->momentum;
        const bool flat = m_frame->scene->topology.dimension < 3;
        const QString momentum = flat ? QStringLiteral("(%1, %2)").arg(num(p.x(), 'g', 4), num(p.y(), 'g', 4))
                                      : QStringLiteral("(%1, %2, %3)").arg(num(p.x(), 'g', 4), num(p.y(), 'g', 4), num(p.z(), 'g', 4));
        html += QStringLiteral("<br>") + tr("momentum %1 kg m/s").arg(momentum).toHtmlEscaped();
        const QString gap = num(lane.world->minGap, 'g', 3);
        html += QStringLiteral("<br>") + (lane.world->minGapBodies[0] >= 0 ? tr("min_gap %1 m").arg(gap)
                                                                          : tr("min_gap beyond %1 m").arg(gap))
                                             .toHtmlEscaped();
    }
    // The distance to the reference view: view 1, or the first live view once view 1 has failed
    // (the Run dock's "distance to view N"); none on the reference view itself.
    const int reference = std::clamp(lane.divergenceReference, 0, int(m_frame->lanes.size()) - 1);
    if (m_frame->lanes.size() > 1 && m_lane != reference && !lane.failure)
        html += QStringLiteral("<br>") + tr("distance from %1: %2 m (RMS)")
                                              .arg(m_frame->lanes[std::size_t(reference)].integrator)
                                              .arg(num(lane.divergence, 'g', 3));
    if (lane.failure)
        html += QStringLiteral("<br><span style='background:#c0392b; color:white'>&nbsp;%1&nbsp;</span>")
                    .arg(tr("Blew up at t = %1 s: %2")
                             .arg(num(lane.failure->time, 'f', 3), failureReason(lane.failure->reason))
                             .toHtmlEscaped());
    if (m_info->text() != html) {
        m_info->setText(html);
        layoutInfo();
    }
    m_legend->setRange(m_options.strainRange);
    m_legend->setVisible(m_options.strain);
    updateForcesPanel(lane);
    updateRulerLabel();  // follows the camera
}

bool Viewport::nearBody(const QPointF& pixel) const {
    if (!m_frame) return false;
    const auto& x = m_frame->lanes[std::size_t(std::clamp(m_lane, 0, int(m_frame->lanes.size()) - 1))].positions;
    const auto& layer = m_frame->scene->topology.layer;
    const QMatrix4x4 mvp = m_camera.projection(size()) * m_camera.view();
    const float limit = 28.0f;
    for (std::size_t i = 0; i < layer.size(); ++i) {
        if (layer[i] == simcore::Layer::Inner) continue;
        const QVector3D ndc = mvp.map(QVector3D(x[3 * i], x[3 * i + 1], x[3 * i + 2]));
        const QPointF p((ndc.x() + 1.0f) * 0.5f * float(width()), (1.0f - ndc.y()) * 0.5f * float(height()));
        if (QLineF(p, pixel).length() < limit) return true;
    }
    return false;
}

QVector3D Viewport::anchorUnder(const QPointF& pixel) const {
    const Ray ray = m_camera.rayAt(pixel, size());
    const float denom = QVector3D::dotProduct(ray.direction, m_planeNormal);
    if (std::abs(denom) < 1e-6f) return m_planePoint;
    const float t = QVector3D::dotProduct(m_planePoint - ray.origin, m_planeNormal) / denom;
    return ray.origin + t * ray.direction;
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    m_lastPixel = event->position();
    m_pressPixel = event->position();
    m_clickCandidate = event->button() == Qt::LeftButton;
    m_contextCandidate = event->button() == Qt::RightButton;
    // Shift+left always orbits (a large body can cover the whole view).
    const bool orbitOnly = event->modifiers() & Qt::ShiftModifier;
    if (event->button() == Qt::LeftButton && m_options.ruler && !orbitOnly) {
        // The ruler: from where the button went down to where it is.
        m_drag = Drag::Ruler;
        m_clickCandidate = false;
        m_rulerA = m_rulerB = onViewPlane(event->position());
        m_hasRuler = true;
        updateRulerLabel();
        update();
    } else if (event->button() == Qt::LeftButton && !orbitOnly && nearBody(event->position())) {
        const Ray ray = m_camera.rayAt(event->position(), size());
        m_drag = Drag::Grab;
        m_grabbed = false;
        emit grabRequested(ray.origin, ray.direction, 28.0 * m_camera.worldPerPixel(size()));
    } else if (event->button() == Qt::LeftButton && !m_camera.is2d()) {
        m_drag = Drag::Orbit;
    } else {
        m_drag = Drag::Pan;
    }
}

void Viewport::onGrabbed(int, const QVector3D& position) {
    if (m_drag != Drag::Grab) return;
    m_grabbed = true;
    m_planePoint = position;
    m_planeNormal = m_camera.forward();
    emit anchorMoved(anchorUnder(m_lastPixel));
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPointF d = event->position() - m_lastPixel;
    m_lastPixel = event->position();
    if (QLineF(m_pressPixel, event->position()).length() > kClickSlop) m_clickCandidate = m_contextCandidate = false;
    switch (m_drag) {
        case Drag::Ruler:
            m_rulerB = onViewPlane(event->position());
            updateRulerLabel();
            update();
            break;
        case Drag::Grab:
            if (m_grabbed) emit anchorMoved(anchorUnder(event->position()));
            break;
        case Drag::Orbit:
            m_camera.orbit(float(d.x()), float(d.y()));
            emit cameraChanged(m_camera);
            update();
            break;
        case Drag::Pan:
            m_camera.pan(float(d.x()), float(d.y()), size());
            emit cameraChanged(m_camera);
            update();
            break;
        case Drag::None: break;
    }
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (m_drag == Drag::Grab) emit releaseRequested();
    const bool click = m_clickCandidate && event->button() == Qt::LeftButton &&
                       QLineF(m_pressPixel, event->position()).length() <= kClickSlop;
    const bool context = m_contextCandidate && event->button() == Qt::RightButton &&
                         QLineF(m_pressPixel, event->position()).length() <= kClickSlop;
    m_clickCandidate = m_contextCandidate = false;
    m_drag = Drag::None;
    m_grabbed = false;
    if (context) emit contextRequested(mapToGlobal(event->position().toPoint()), particleAt(m_pressPixel));
    if (click) {
        // A click: select what is under the cursor (the worker picks; nothing near: clear).
        const Ray ray = m_camera.rayAt(m_pressPixel, size());
        emit selectRequested(ray.origin, ray.direction, 28.0 * m_camera.worldPerPixel(size()));
    }
}

void Viewport::wheelEvent(QWheelEvent* event) {
    m_camera.zoom(float(event->angleDelta().y()) / 120.0f);
    emit cameraChanged(m_camera);
    update();
}

}  // namespace elui
