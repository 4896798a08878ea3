#include "ui/camera.h"

#include <algorithm>
#include <cmath>

namespace elui {

void Camera::fit(const QVector3D& centre, float bodyRadius, float boxHalfSize) {
    m_homeTarget = centre;
    // 2D: the whole box (a dropped body must stay in view). 3D: the body large, with some of
    // the box around it.
    const float extent = m_flat ? boxHalfSize * 1.06f : std::min(boxHalfSize, bodyRadius * 1.6f) * 1.15f;
    m_homeHalfHeight = std::max(extent, bodyRadius * 1.2f);
    m_homeDistance = m_homeHalfHeight / std::tan(0.5f * m_fovY * float(M_PI) / 180.0f) * 1.25f;
    resetView();
}

void Camera::resetView() {
    m_target = m_homeTarget;
    m_distance = m_homeDistance;
    m_halfHeight = m_homeHalfHeight;
    m_halfWidth = m_homeHalfHeight;
    m_yaw = 0.6f;
    m_pitch = 0.35f;
}

void Camera::orbit(float dx, float dy) {
    if (m_flat) return;
    m_yaw -= dx * 0.008f;
    m_pitch = std::clamp(m_pitch + dy * 0.008f, -1.5f, 1.5f);
}

void Camera::pan(float dx, float dy, const QSize& viewport) {
    const float s = worldPerPixel(viewport);
    const QVector3D f = forward();
    QVector3D right = QVector3D::crossProduct(f, QVector3D(0, 1, 0)).normalized();
    if (m_flat) right = QVector3D(1, 0, 0);
    const QVector3D up = m_flat ? QVector3D(0, 1, 0) : QVector3D::crossProduct(right, f).normalized();
    m_target += (-dx * right + dy * up) * s;
}

void Camera::zoom(float steps) {
    const float factor = std::pow(0.85f, steps);
    m_distance = std::clamp(m_distance * factor, 0.5f, 500.0f);
    m_halfHeight = std::clamp(m_halfHeight * factor, 0.05f, 500.0f);
    m_halfWidth = std::clamp(m_halfWidth * factor, 0.05f, 500.0f);
}

float Camera::flatHalfHeight(const QSize& viewport) const {
    const float aspect = float(std::max(1, viewport.width())) / float(std::max(1, viewport.height()));
    return std::max(m_halfHeight, m_halfWidth / aspect);
}

QVector3D Camera::eye() const {
    if (m_flat) return m_target + QVector3D(0, 0, 100.0f);
    return m_target + m_distance * QVector3D(std::cos(m_pitch) * std::sin(m_yaw), std::sin(m_pitch),
                                             std::cos(m_pitch) * std::cos(m_yaw));
}

QVector3D Camera::forward() const { return (m_target - eye()).normalized(); }

QMatrix4x4 Camera::view() const {
    QMatrix4x4 v;
    v.lookAt(eye(), m_target, QVector3D(0, 1, 0));
    return v;
}

QMatrix4x4 Camera::projection(const QSize& viewport) const {
    const float aspect = float(std::max(1, viewport.width())) / float(std::max(1, viewport.height()));
    QMatrix4x4 p;
    if (m_flat)
    {
        const float hh = flatHalfHeight(viewport);
        p.ortho(-hh * aspect, hh * aspect, -hh, hh, 1.0f, 200.0f);
    }
    else
        p.perspective(fovY(viewport), aspect, std::max(0.05f, m_distance * 0.02f), m_distance * 20.0f);
    return p;
}

float Camera::fovY(const QSize& viewport) const {
    // A view taller than wide keeps m_fovY across its width (the framing fit() chose holds
    // on the narrow side: the body is not cut at the sides of a narrow view), so its vertical
    // angle grows: tan(fovY / 2) = tan(m_fovY / 2) / aspect.
    const float aspect = float(std::max(1, viewport.width())) / float(std::max(1, viewport.height()));
    const float halfTan = std::tan(0.5f * m_fovY * float(M_PI) / 180.0f);
    return aspect >= 1.0f ? m_fovY : 2.0f * std::atan(halfTan / aspect) * 180.0f / float(M_PI);
}

Ray Camera::rayAt(const QPointF& pixel, const QSize& viewport) const {
    const QMatrix4x4 inverse = (projection(viewport) * view()).inverted();
    const float x = float(2.0 * pixel.x() / std::max(1, viewport.width()) - 1.0);
    const float y = float(1.0 - 2.0 * pixel.y() / std::max(1, viewport.height()));
    const QVector3D nearPoint = inverse.map(QVector3D(x, y, -1.0f));
    const QVector3D farPoint = inverse.map(QVector3D(x, y, 1.0f));
    return {nearPoint, (farPoint - nearPoint).normalized()};
}

float Camera::worldPerPixel(const QSize& viewport) const {
    const float h = float(std::max(1, viewport.height()));
    if (m_flat) return 2.0f * flatHalfHeight(viewport) / h;
    return 2.0f * m_distance * std::tan(0.5f * fovY(viewport) * float(M_PI) / 180.0f) / h;
}

}  // namespace elui
