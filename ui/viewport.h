#pragma once
// Viewport: draws one lane of the newest frame with OpenGL 3.3 core (shaders in resources/).
//
// Buffers: positions are the only per-frame upload (plus force vectors when shown). Index
// buffers (springs per family, faces, the 2D fill), particle layers and the rest lengths
// used for strain colouring are uploaded when the scene changes, i.e. on a rebuild.
//
// Mouse: left press on the body grabs the nearest outer particle under the cursor (the
// worker picks along the ray with simcore's pickAlongRay); dragging moves the anchor in the
// plane through the particle facing the camera. Left drag elsewhere orbits (3D), right or
// middle drag pans, the wheel zooms.
//
// A left click without a drag (released within kClickSlop pixels, the mouse spring let go at
// once) selects the particle under the cursor: its free-body diagram, one arrow per force part
// from the particle and the total, and a panel of their magnitudes (frames carry the
// breakdown, the worker computes it). A click away from the body clears it.
//
// Keyboard (with focus, shown by a frame): arrow keys and Page Up/Down choose a particle (its
// forces as for a click), Enter grabs it and the arrows drag it, Enter or Escape let go.

#include <array>
#include <memory>

#include <QElapsedTimer>
#include <QOpenGLBuffer>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>

#include "ui/camera.h"
#include "ui/frame.h"
#include "ui/view_options.h"

class QFrame;
class QLabel;

namespace elui {

class StrainLegend;

class Viewport : public QOpenGLWidget, protected QOpenGLFunctions_3_3_Core {
    Q_OBJECT
public:
    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    // False where a QOpenGLWidget cannot work (the offscreen platform, no GL 3.3).
    static bool openGLAvailable();
    // What the particle shader reads per particle: the layer (0 single, 1 inner, 2 outer), plus
    // 4 (k + 1) for body k of a world, drawn in its hue (bodyColor; the inner layer darker).
    static std::vector<float> particleCodes(const SceneData& scene);
    // GL_RENDERER of the probe context ("" before openGLAvailable() or without GL).
    static QString rendererName();
    // True for Mesa's CPU renderers (llvmpipe, softpipe, swrast).
    static bool softwareRenderer();
    // Multisampling of viewports created from now on (< 0: the default format's).
    static void setSamples(int samples);

    void setLane(int lane) { m_lane = lane; }
    int lane() const { return m_lane; }
    void setOptions(const ViewOptions& options);
    const ViewOptions& options() const { return m_options; }
    Camera& camera() { return m_camera; }
    void setCamera(const Camera& camera);
    void setTitle(const QString& title) {
        m_title = title;
        updateOverlay();
    }
    FramePtr frame() const { return m_frame; }
    // Frames drawn since creation (for frame-rate measurements).
    quint64 paintCount() const { return m_paints; }
    // The particle drawn nearest a pixel, within 28 px (any layer), or -1.
    int particleAt(const QPointF& pixel) const;
    // The ruler (ViewOptions::ruler): its length [m] (0: none drawn), and the label shown.
    double rulerLength() const;
    QString rulerText() const;
    QString overlayText() const;  // the text over the view (title, time, distance, failure)

    // High contrast (View menu): black background, white structural springs, yellow focus frame.
    void setHighContrast(bool on);

public slots:
    void showFrame(const elui::FramePtr& frame);
    void resetView();
    void onGrabbed(int particle, const QVector3D& position);

signals:
    void grabRequested(const QVector3D& origin, const QVector3D& direction, double maxDistance);
    void anchorMoved(const QVector3D& anchor);
    void releaseRequested();
    // A click without a drag: select the particle nearest the ray (none near it: clear).
    void selectRequested(const QVector3D& origin, const QVector3D& direction, double maxDistance);
    // A right click (no drag) at a global position, on a particle (its index) or not (-1).
    void contextRequested(const QPoint& globalPosition, int particle);
    void cameraChanged(const elui::Camera& camera);
    // The keyboard chose a particle (arrow keys, Page Up/Down), or none (-1, Escape).
    void particleSelected(int particle);

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    struct Elements {
        mutable QOpenGLBuffer buffer{QOpenGLBuffer::IndexBuffer};
        int count = 0;
    };
    void cleanup();
    void uploadScene();
    void uploadSprings(const simcore::Topology& topo);  // the three families and their rest lengths
    void uploadBodyFaces(const SceneData& scene);       // each body's own faces (bodyFaces)
    static void uploadIndices(Elements& e, const std::vector<GLuint>& indices);
    void uploadPositions(const LaneFrame& lane);
    void drawElementsLines(const Elements& e, const QVector4D& color, float width, int family);
    void drawSegments(const std::vector<float>& xyz, const QVector4D& color, float width);
    void drawSurface(const Elements& e, const QVector4D& color, bool lit);
    void drawPolygonStencil(const Elements& fan, const QVector4D& color);
    void drawBox();
    // paintGL's parts, in the order they draw.
    void drawInnerFaces(const SceneData& scene, bool flat);
    void drawNormals(const SceneData& scene, const LaneFrame& lane, bool flat);
    void drawPointer(const LaneFrame& lane, bool flat);
    void drawOuterFaces(const SceneData& scene);
    QElapsedTimer m_overlayClock;  // the overlay's last refresh while running
    void updateOverlay();
    void layoutInfo();
    bool nearBody(const QPointF& pixel) const;
    // The selected particle's force arrows, and the panel that names them.
    void drawForceBreakdown(const LaneFrame& lane);
    // Arrows from every particle along `vectors` (3N), the 90th percentile 0.4 body radii long.
    void drawArrows(const std::vector<float>& x, const std::vector<float>& vectors, const QVector4D& color);
    void drawRuler();
    void updateRulerLabel();
    QPointF toPixel(const QVector3D& point) const;
    QVector3D onViewPlane(const QPointF& pixel) const;
    void updateForcesPanel(const LaneFrame& lane);
    QVector3D anchorUnder(const QPointF& pixel) const;
    QPointF pixelOf(int particle) const;  // where a particle of the shown lane is drawn
    void resizeEventFrame();

    FramePtr m_frame;
    std::shared_ptr<const SceneData> m_uploadedScene;
    int m_lane = 0;
    ViewOptions m_options;
    Camera m_camera;
    QString m_title;
    quint64 m_paints = 0;
    bool m_glReady = false;
    // Text and legend are child widgets over the GL image (composited by Qt, kept in grab()).
    QLabel* m_info = nullptr;
    StrainLegend* m_legend = nullptr;
    QLabel* m_forcesPanel = nullptr;  // the selected particle's forces (objectName "forcesPanel")
    QLabel* m_rulerLabel = nullptr;   // the ruler's length (objectName "rulerLabel")
    bool m_hasRuler = false;
    QVector3D m_rulerA, m_rulerB;     // the ruler's ends [m], on the view's plane
    double m_arrowScale = 0.0;        // of the force arrows drawn last [m per N]

    // GL objects (made in initializeGL, freed on aboutToBeDestroyed).
    std::unique_ptr<QOpenGLShaderProgram> m_lines, m_normals, m_surface, m_points;
    QOpenGLVertexArrayObject m_vao;
    QOpenGLBuffer m_positions{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer m_layers{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer m_scratch{QOpenGLBuffer::VertexBuffer};  // segments: box, mouse spring, forces
    QOpenGLVertexArrayObject m_scratchVao;
    std::array<Elements, 3> m_springs;
    std::array<GLuint, 3> m_restBuffers{}, m_restTextures{};
    Elements m_innerFaces, m_outerFaces, m_fill, m_innerFan, m_outerFan;
    // A scene of several bodies: each body's outer faces (3D) or ring fill (2D), in its hue.
    std::vector<Elements> m_bodyFaces;
    void releaseBodyFaces();
    int m_particleCount = 0;

    // Mouse.
    enum class Drag { None, Orbit, Pan, Grab, Ruler };
    Drag m_drag = Drag::None;
    QPointF m_lastPixel;
    QPointF m_pressPixel;     // where the left button went down
    bool m_clickCandidate = false;  // left press not (yet) moved beyond the slop: a click
    bool m_contextCandidate = false;  // the same for the right button: a context menu
    bool m_grabbed = false;
    QVector3D m_planePoint;   // the drag plane passes through here, facing the camera
    QVector3D m_planeNormal;

    // Keyboard (issue 30): the particle chosen with the arrow keys (-1: none), the focus frame.
    int m_keyboardParticle = -1;
    QFrame* m_focusFrame = nullptr;
    bool m_highContrast = false;
};

}  // namespace elui
