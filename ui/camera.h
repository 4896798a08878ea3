#pragma once
// Camera: an orbiting perspective camera for 3D scenes, an orthographic one for 1D and 2D.
//
//   3D: eye = target + distance * (cos p sin y, sin p, cos p cos y); orbit changes yaw/pitch,
//       pan moves the target in the view plane, zoom scales the distance.
//   2D: looks down -z at the xy plane; pan moves the centre, zoom scales the half-height.

#include <QMatrix4x4>
#include <QPointF>
#include <QSize>
#include <QVector3D>

namespace elui {

struct Ray {
    QVector3D origin;
    QVector3D direction;  // unit
};

class Camera {
public:
    void setMode2d(bool flat) { m_flat = flat; }
    bool is2d() const { return m_flat; }
    // Frames a body of the given radius inside a box of the given half-size.
    void fit(const QVector3D& centre, float bodyRadius, float boxHalfSize);
    void resetView();

    void orbit(float dxPixels, float dyPixels);
    void pan(float dxPixels, float dyPixels, const QSize& viewport);
    void zoom(float wheelSteps);

    QMatrix4x4 view() const;
    QMatrix4x4 projection(const QSize& viewport) const;
    QVector3D eye() const;
    QVector3D forward() const;  // unit, from the eye towards the target
    // The ray under a widget pixel (origin on the near plane).
    Ray rayAt(const QPointF& pixel, const QSize& viewport) const;
    // World length of one pixel at the target's depth.
    float worldPerPixel(const QSize& viewport) const;
    // 3D: the vertical field of view in a viewport of this size [deg]: the camera's 40 degrees,
    // or more in a view taller than wide, so that 40 degrees fit across its width.
    float fovY(const QSize& viewport) const;

    bool operator==(const Camera&) const = default;

private:
    bool m_flat = false;
    QVector3D m_target;
    float m_yaw = 0.6f, m_pitch = 0.35f, m_distance = 10.0f;  // [rad], [rad], [m]
    float m_halfHeight = 3.0f;                                 // 2D [m]
    float m_halfWidth = 3.0f;                                  // 2D: at least this wide [m]
    float m_fovY = 40.0f;                                      // [deg]
    // The framing fit() chose, for resetView().
    QVector3D m_homeTarget;
    float m_homeDistance = 10.0f, m_homeHalfHeight = 3.0f;
    // The 2D half-height that shows at least m_halfWidth across a viewport of this size.
    float flatHalfHeight(const QSize& viewport) const;
};

}  // namespace elui
