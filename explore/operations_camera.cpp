// The camera's moves (operations.h): the orbit and zoom of a drag and the
// wheel on the display, R's reset, and Shift+drag's move of an object.
#include "explore/operations.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace m3055::explore {

namespace {
using numeric::kPi;

// Rodrigues' rotation of v by `angle` radians about the unit axis k.
dvec3 rotate(const dvec3& v, double angle, const dvec3& k) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
}

// Radians of orbit per pixel dragged: a 300-pixel drag turns about 90 degrees.
constexpr double kOrbitPerPixel = 0.3 * kPi / 180.0;
// Keep the view direction at least this far (radians) from `up` (docs/spec.md#7-scene-files).
constexpr double kPoleMargin = 0.02;
// One wheel step moves 10 % closer.
constexpr double kZoomPerStep = 0.9;
}  // namespace

bool apply(Explorer& e, const command::OrbitCamera& move) {
    const double dx_pixels = move.dx, dy_pixels = move.dy;
    Camera c = e.doc.scene.camera;
    const dvec3 up = glm::normalize(c.up);
    dvec3 offset = c.position - c.target;
    // Dragging right turns the camera left around the object (the object seems to turn right).
    offset = rotate(offset, -dx_pixels * kOrbitPerPixel, up);
    // Dragging down raises the camera, clamped short of the poles.
    const double radius = glm::length(offset);
    const double polar = std::acos(std::clamp(glm::dot(offset / radius, up), -1.0, 1.0));
    const double wanted = std::clamp(polar - dy_pixels * kOrbitPerPixel, kPoleMargin,
                                     kPi - kPoleMargin);
    const dvec3 right = glm::normalize(glm::cross(offset, up));
    offset = rotate(offset, polar - wanted, right);
    c.position = c.target + offset;
    edit_document(e, {CameraEdit{e.doc.scene.camera, c}, "orbit camera"});
    return true;
}

bool apply(Explorer& e, const command::ZoomCamera& zoom) {
    Camera c = e.doc.scene.camera;
    const double factor = std::pow(kZoomPerStep, zoom.steps);
    if (c.projection == Projection::orthographic) {
        c.height = std::clamp(c.height * factor, 1e-3, 1e4);
    } else {
        const dvec3 offset = c.position - c.target;
        const double distance = std::clamp(glm::length(offset) * factor, 1e-2, 1e4);
        c.position = c.target + glm::normalize(offset) * distance;
    }
    edit_document(e, {CameraEdit{e.doc.scene.camera, c}, "zoom camera"});
    return true;
}

bool apply(Explorer& e, const command::MoveObjectInView& move) {
    const double dx = move.dx, dy = move.dy, shown_height = move.shown_height;
    const int index = e.view.selected_object;
    if (index < 0 || index >= static_cast<int>(e.doc.scene.objects.size()) || !(shown_height > 0.0)) return false;
    const Camera& c = e.doc.scene.camera;
    Object object = e.doc.scene.objects[std::size_t(index)];
    const dvec3 forward = glm::normalize(c.target - c.position);
    const dvec3 right = glm::normalize(glm::cross(forward, c.up));
    const dvec3 up = glm::cross(right, forward);
    // World units per window unit at the object's depth: the view's height
    // there (orthographic: the camera's; perspective: 2 d tan(fov/2)) over
    // the height the display is shown at.
    const double depth = glm::dot(object.center - c.position, forward);
    const double view_height = c.projection == Projection::orthographic
                                   ? c.height
                                   : 2.0 * std::max(depth, 1e-3) * std::tan(c.fov_y_deg * kPi / 360.0);
    const double per_unit = view_height / shown_height;
    object.center += right * (dx * per_unit) - up * (dy * per_unit);
    edit_document(e, {ObjectEdit{index, e.doc.scene.objects[std::size_t(index)], object},
                      "move objects[" + std::to_string(index) + "]"});
    return true;
}

bool apply(Explorer& e, const command::ResetCamera&) {
    edit_document(e, {CameraEdit{e.doc.scene.camera, e.doc.camera_home}, "reset camera"});
    return true;
}

bool apply(Explorer& e, const command::SetCamera& c) {
    edit_document(e, {CameraEdit{e.doc.scene.camera, c.value}, ""});
    return true;
}

}  // namespace m3055::explore
