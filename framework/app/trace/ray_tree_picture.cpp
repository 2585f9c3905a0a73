// The ray tree drawn over the scene: as the eye sees it, and from the side.
#include "trace/ray_tree_report.hpp"

#include <algorithm>
#include <cmath>

namespace whitted {
namespace {

const Color kEyeColor(1.0, 1.0, 1.0);
const Color kReflectedColor(0.0, 1.0, 1.0);
const Color kRefractedColor(0.2, 1.0, 0.2);
const Color kLitFeelerColor(1.0, 0.9, 0.0);
const Color kBlockedFeelerColor(1.0, 0.1, 0.1);
const Color kMarkColor(1.0, 0.0, 1.0);
const Color kSideBackground(0.05, 0.05, 0.12);

// One picture inside the big one, seen through its camera.
struct Panel {
    Image& canvas;
    int left; // x of the panel's first column in the canvas
    const Camera& camera;

    void plot(int x, int y, const Color& color) {
        if (x < 0 || y < 0 || x >= camera.res_x || y >= camera.res_y) return;
        canvas.at(left + x, y) = color;
    }

    // Image position (column, row from the top) of a point in front of the camera.
    Vec2 to_image(const Point3& p) const {
        const Vec3 d = p - camera.eye;
        const double forward = -glm::dot(d, camera.ze);
        const double u = glm::dot(d, camera.xe) / forward * camera.df / camera.w;
        const double v = glm::dot(d, camera.ye) / forward * camera.df / camera.h;
        return {(u + 0.5) * camera.res_x, (0.5 - v) * camera.res_y};
    }

    // Draws the part of segment ab in front of the camera; dashed lines skip every other 4 pixels.
    void segment(Point3 a, Point3 b, const Color& color, bool dashed = false) {
        if (!is_finite(a) || !is_finite(b)) return; // a NaN ray from buggy code: nothing to draw
        const double near = 1e-3 * camera.df;
        const double fa = -glm::dot(a - camera.eye, camera.ze), fb = -glm::dot(b - camera.eye, camera.ze);
        if (fa < near && fb < near) return;
        if (fa < near) a = a + (b - a) * ((near - fa) / (fb - fa));
        if (fb < near) b = b + (a - b) * ((near - fb) / (fa - fb));
        line(to_image(a), to_image(b), color, dashed);
    }

    void line(Vec2 a, Vec2 b, const Color& color, bool dashed) {
        if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) return;
        // Clip to the panel first (Liang-Barsky), so far-away ends cost nothing.
        double t0 = 0.0, t1 = 1.0;
        const Vec2 d = b - a;
        const double p[4] = {-d.x, d.x, -d.y, d.y};
        const double q[4] = {a.x + 1.0, camera.res_x - a.x, a.y + 1.0, camera.res_y - a.y};
        for (int i = 0; i < 4; ++i) {
            if (p[i] == 0.0) {
                if (q[i] < 0.0) return;
                continue;
            }
            const double r = q[i] / p[i];
            if (p[i] < 0.0) t0 = std::max(t0, r);
            else t1 = std::min(t1, r);
        }
        if (!(t0 <= t1)) return;
        const Vec2 from = a + d * t0, to = a + d * t1;
        const int steps = std::max(1, static_cast<int>(std::ceil(std::max(std::abs(to.x - from.x), std::abs(to.y - from.y)))));
        for (int i = 0; i <= steps; ++i) {
            if (dashed && (i / 4) % 2 == 1) continue;
            const Vec2 q2 = from + (to - from) * (static_cast<double>(i) / steps);
            const int px = static_cast<int>(std::floor(q2.x)), py = static_cast<int>(std::floor(q2.y));
            plot(px, py, color); // two pixels wide
            plot(px + 1, py, color);
            plot(px, py + 1, color);
        }
    }

    void dot(const Point3& p, const Color& color) {
        if (!is_finite(p)) return;
        if (-glm::dot(p - camera.eye, camera.ze) < 1e-3 * camera.df) return;
        const Vec2 q = to_image(p);
        if (!(std::abs(q.x) < 1e6 && std::abs(q.y) < 1e6)) return;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) plot(static_cast<int>(std::floor(q.x)) + dx, static_cast<int>(std::floor(q.y)) + dy, color);
    }

    void cross(const Point3& p, const Color& color) {
        if (!is_finite(p) || -glm::dot(p - camera.eye, camera.ze) < 1e-3 * camera.df) return;
        const Vec2 q = to_image(p);
        if (!(std::abs(q.x) < 1e6 && std::abs(q.y) < 1e6)) return;
        for (int d = -4; d <= 4; ++d) {
            const int x = static_cast<int>(std::floor(q.x)), y = static_cast<int>(std::floor(q.y));
            plot(x + d, y + d, color);
            plot(x + d, y - d, color);
        }
    }

    void draw_tree(const RayTree& tree, double miss_length) {
        for (const RayNode& node : tree.nodes) {
            if (node.fate != RayFate::traced) continue;
            if (node.kind == RayKind::shadow) {
                const bool blocked = node.blocked && node.hit;
                const Point3 end = blocked ? node.hit->point : node.ray.at(node.light_distance);
                segment(node.ray.origin, end, blocked ? kBlockedFeelerColor : kLitFeelerColor, !blocked);
                if (blocked) cross(end, kBlockedFeelerColor); // visible even when the feeler is 1e-16 long
                continue;
            }
            const Color& color = node.kind == RayKind::eye       ? kEyeColor
                                 : node.kind == RayKind::reflected ? kReflectedColor
                                                                   : kRefractedColor;
            const Point3 end = node.hit ? node.hit->point : node.ray.at(miss_length);
            segment(node.ray.origin, end, color);
            if (node.hit) dot(end, color);
        }
    }
};

// The points where the tree's story happens: the hits, and the origins of the
// secondary rays (the eye, usually far away, only makes the picture small).
std::vector<Point3> tree_points(const RayTree& tree) {
    std::vector<Point3> points;
    for (const RayNode& node : tree.nodes) {
        if (node.fate != RayFate::traced) continue;
        if (node.kind != RayKind::eye && is_finite(node.ray.origin)) points.push_back(node.ray.origin);
        if (node.hit && is_finite(node.hit->point)) points.push_back(node.hit->point);
    }
    return points; // empty when the eye ray saw the background

}

double tree_size(const RayTree& tree) {
    const std::vector<Point3> points = tree_points(tree);
    if (points.empty()) return 0.0;
    double size = 0.0;
    for (const Point3& p : points) size = std::max(size, glm::length(p - points.front()));
    return size;
}

} // namespace

Camera side_camera_for(const RayTree& tree, const Camera& eye_camera, int width, int height) {
    std::vector<Point3> points = tree_points(tree);
    if (points.empty()) points.push_back(eye_camera.at);
    Point3 low = points.front(), high = points.front();
    for (const Point3& p : points) low = glm::min(low, p), high = glm::max(high, p);
    const Point3 centre = 0.5 * (low + high);
    double radius = 0.0;
    for (const Point3& p : points) radius = std::max(radius, glm::length(p - centre));
    if (!(radius > 1e-9 * (1.0 + max_abs_component(centre)))) radius = eye_camera.df;
    const double fovy = 40.0;
    const double distance = 1.25 * radius / std::tan(radians(fovy / 2.0)) * std::max(1.0, double(height) / width);
    return Camera::create(centre + eye_camera.xe * distance, centre, eye_camera.ye, fovy, width, height);
}

Image ray_tree_picture(const RayTree& tree, const TraceContext& context, const Image& eye_view,
                       const Image& side_normals, const Camera& side_camera) {
    const int gap = 4;
    Image canvas(eye_view.width + gap + side_normals.width, std::max(eye_view.height, side_normals.height), Color(1.0));
    // The render, dimmed so that the rays stand out.
    for (int y = 0; y < eye_view.height; ++y)
        for (int x = 0; x < eye_view.width; ++x) canvas.at(x, y) = 0.55 * glm::clamp(eye_view.at(x, y), 0.0, 1.0);
    // The side view: plain grey shapes, lighter where they face the viewer, so
    // that glass, mirrors or a wrong material cannot hide them.
    for (int y = 0; y < side_normals.height; ++y) {
        for (int x = 0; x < side_normals.width; ++x) {
            const Color& c = side_normals.at(x, y);
            const double facing = std::abs(glm::dot(2.0 * c - 1.0, side_camera.ze));
            canvas.at(eye_view.width + gap + x, y) = c == Color(0.0) ? kSideBackground : Color(0.15 + 0.4 * facing);
        }
    }
    for (Color& c : canvas.pixels)
        if (!is_finite(c)) c = kMarkColor;

    const double miss_length = std::max(2.0 * tree_size(tree), context.scene.camera().df);
    const Camera eye_camera = context.scene.camera().with_resolution(eye_view.width, eye_view.height);
    Panel eye{canvas, 0, eye_camera};
    eye.draw_tree(tree, miss_length);
    // A ring around the traced pixel (the panels may be larger than the image traced).
    const double scale = static_cast<double>(eye_view.width) / context.width;
    const double cx = (context.x + 0.5) * scale, cy = (context.y + 0.5) * scale;
    for (int a = 0; a < 96; ++a) {
        const double angle = 2.0 * kPi * a / 96.0;
        eye.plot(static_cast<int>(std::floor(cx + 9.0 * std::cos(angle))),
                 static_cast<int>(std::floor(cy + 9.0 * std::sin(angle))), kMarkColor);
    }
    Panel side{canvas, eye_view.width + gap, side_camera};
    side.draw_tree(tree, miss_length);
    return canvas;
}

} // namespace whitted
