#include "wire.hpp"

#include <algorithm>

namespace whitted::link {

void write_frame(Channel& channel, FrameType type, const std::vector<std::byte>& payload) {
    if (payload.size() > 0xFFFFFFF0u) throw LinkError("a message too large to send");
    std::vector<std::byte> frame(5 + payload.size());
    const auto length = static_cast<std::uint32_t>(payload.size());
    std::memcpy(frame.data(), &length, 4);
    frame[4] = static_cast<std::byte>(type);
    if (!payload.empty()) std::memcpy(frame.data() + 5, payload.data(), payload.size());
    channel.write(frame.data(), frame.size());
}

void FrameReader::fill(std::size_t bytes) {
    while (end_ - start_ < bytes) {
        if (start_ > 0) { // keep only what is still unread, at the front
            std::memmove(buffer_.data(), buffer_.data() + start_, end_ - start_);
            end_ -= start_;
            start_ = 0;
        }
        // The buffer only grows (zero-filled then, never on each read: that cost half of a sampling lab's time).
        if (buffer_.size() < std::max<std::size_t>(bytes, 65536)) buffer_.resize(std::max<std::size_t>(bytes, 65536));
        end_ += channel_.read_some(buffer_.data() + end_, buffer_.size() - end_);
    }
}

Frame FrameReader::next() {
    fill(5);
    std::uint32_t length = 0;
    std::memcpy(&length, buffer_.data() + start_, 4);
    const auto type = static_cast<std::uint8_t>(buffer_[start_ + 4]);
    if (type < 1 || type > 5) throw LinkError("a message of unknown type " + std::to_string(type));
    if (length > max_bytes_)
        throw LinkError("a message of " + std::to_string(length) + " bytes, over the limit of " +
                        std::to_string(max_bytes_));
    fill(5 + std::size_t{length});
    Frame frame;
    frame.type = static_cast<FrameType>(type);
    const auto* begin = buffer_.data() + start_ + 5;
    frame.payload.assign(begin, begin + length);
    start_ += 5 + std::size_t{length};
    return frame;
}

// ---- Writer --------------------------------------------------------------------------

void Writer::put(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    const std::size_t at = bytes_.size();
    bytes_.resize(at + text.size());
    if (!text.empty()) std::memcpy(bytes_.data() + at, text.data(), text.size());
}
void Writer::put(const Ray& ray) { put(ray.origin), put(ray.direction); }
void Writer::put(const Interval& interval) { put(interval.min), put(interval.max); }
void Writer::put(const Hit& hit) {
    put(hit.t), put(hit.point), put(hit.normal), put(hit.geometric_normal), put(hit.front_face), put(hit.uv);
    put(hit.primitive), put(hit.material);
}
void Writer::put(const Camera& c) {
    put(c.eye), put(c.at), put(c.up), put(c.fovy), put(c.res_x), put(c.res_y);
    put(c.df), put(c.h), put(c.w), put(c.xe), put(c.ye), put(c.ze);
    put(c.aperture), put(c.focal_ratio);
}
void Writer::put(const Shape& shape) {
    raw(static_cast<std::uint8_t>(shape.index()));
    std::visit(
        [&](const auto& s) {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, Sphere>) put(s.center), put(s.radius), put(s.inward);
            else if constexpr (std::is_same_v<T, Plane>) put(s.point), put(s.normal);
            else if constexpr (std::is_same_v<T, Triangle>) put(s.p0), put(s.p1), put(s.p2);
            else if constexpr (std::is_same_v<T, Box>) put(s.min), put(s.max);
            else put(s.base), put(s.base_radius), put(s.apex), put(s.apex_radius), put(s.inward);
        },
        shape);
}
void Writer::put(const Primitive& p) {
    put(p.shape), put(p.material), raw(p.vertex_normals), put(p.index), put(p.line);
}
void Writer::put(const Material& m) {
    put(m.color), put(m.diffuse), put(m.specular_color), put(m.specular), put(m.shininess);
    put(m.transmittance), put(m.ior), put(m.checker.has_value());
    if (m.checker) put(m.checker->color_a), put(m.checker->color_b), put(m.checker->size);
}
void Writer::put(const PointLight& light) { put(light.position), put(light.color); }
void Writer::put(const Aabb& box) { put(box.min), put(box.max); }
void Writer::put(const BvhTree& tree) {
    put(static_cast<std::uint64_t>(tree.nodes.size()));
    for (const BvhNode& node : tree.nodes) put(node.bounds), put(node.first), put(node.count);
    put(static_cast<std::uint64_t>(tree.order.size()));
    for (std::uint32_t index : tree.order) put(index);
}
void Writer::put(const AreaLight& light) {
    put(light.center), put(light.color), put(light.edge_u), put(light.edge_v), put(light.samples), put(light.first_number);
}
void Writer::put(const RenderSettings& s) {
    put(s.stage), put(s.max_depth), put(s.min_weight), put(s.max_rays_per_pixel), put(s.samples_per_pixel);
}
void Writer::put(const RayStats& s) {
    put(s.eye), put(s.shadow), put(s.reflected), put(s.refracted), put(s.pixels_cut_short);
}
void Writer::put(const TracerState& s) {
    put(s.stats), put(s.path_weight), put(s.pixel_rays), put(s.pixel_cut_short);
    put(s.sample.x), put(s.sample.y), put(s.sample.index);
}
void Writer::put(const SceneData& d) {
    put(d.camera), put(d.background), put(d.ambient);
    put_all(d.lights), put_all(d.area_lights), put_all(d.materials), put_all(d.primitives);
    put(static_cast<std::uint64_t>(d.vertex_normals.size()));
    for (const VertexNormals& normals : d.vertex_normals) put(normals[0]), put(normals[1]), put(normals[2]);
    put(d.max_depth), put(d.samples_per_pixel), put(static_cast<int>(d.acceleration));
    put(d.skybox != nullptr);
    if (d.skybox)
        for (const SkyboxFace& face : d.skybox->faces())
            put(face.width), put(face.height), put(std::string(face.rgb.begin(), face.rgb.end()));
}

// ---- Reader --------------------------------------------------------------------------

std::size_t Reader::count(std::size_t item_bytes) {
    const auto n = raw<std::uint64_t>();
    if (item_bytes == 0 || n > (bytes_.size() - position_) / item_bytes) throw LinkError("a message with a bad count");
    return static_cast<std::size_t>(n);
}

template <> bool Reader::get<bool>() {
    const auto value = raw<std::uint8_t>();
    if (value > 1) throw LinkError("a message with a bad truth value");
    return value == 1;
}
template <> Vec2 Reader::get<Vec2>() {
    const double x = raw<double>();
    return Vec2(x, raw<double>());
}
template <> Vec3 Reader::get<Vec3>() {
    const double x = raw<double>(), y = raw<double>();
    return Vec3(x, y, raw<double>());
}
template <> std::string Reader::get<std::string>() {
    const std::size_t size = count(1);
    std::string text(reinterpret_cast<const char*>(bytes_.data() + position_), size);
    position_ += size;
    return text;
}
template <> Ray Reader::get<Ray>() {
    Ray ray;
    ray.origin = get<Vec3>();
    ray.direction = get<Vec3>();
    return ray;
}
template <> Interval Reader::get<Interval>() {
    Interval interval;
    interval.min = get<double>();
    interval.max = get<double>();
    return interval;
}
template <> Hit Reader::get<Hit>() {
    Hit hit;
    hit.t = get<double>();
    hit.point = get<Vec3>();
    hit.normal = get<Vec3>();
    hit.geometric_normal = get<Vec3>();
    hit.front_face = get<bool>();
    hit.uv = get<Vec2>();
    hit.primitive = get<std::uint32_t>();
    hit.material = get<std::uint32_t>();
    return hit;
}
template <> Camera Reader::get<Camera>() {
    Camera c;
    c.eye = get<Vec3>(), c.at = get<Vec3>(), c.up = get<Vec3>(), c.fovy = get<double>();
    c.res_x = get<int>(), c.res_y = get<int>();
    c.df = get<double>(), c.h = get<double>(), c.w = get<double>();
    c.xe = get<Vec3>(), c.ye = get<Vec3>(), c.ze = get<Vec3>();
    c.aperture = get<double>(), c.focal_ratio = get<double>();
    return c;
}
template <> Shape Reader::get<Shape>() {
    switch (raw<std::uint8_t>()) {
    case 0: {
        Sphere s;
        s.center = get<Vec3>(), s.radius = get<double>(), s.inward = get<bool>();
        return s;
    }
    case 1: {
        Plane s;
        s.point = get<Vec3>(), s.normal = get<Vec3>();
        return s;
    }
    case 2: {
        Triangle s;
        s.p0 = get<Vec3>(), s.p1 = get<Vec3>(), s.p2 = get<Vec3>();
        return s;
    }
    case 3: {
        Box s;
        s.min = get<Vec3>(), s.max = get<Vec3>();
        return s;
    }
    case 4: {
        Cone s;
        s.base = get<Vec3>(), s.base_radius = get<double>(), s.apex = get<Vec3>(), s.apex_radius = get<double>();
        s.inward = get<bool>();
        return s;
    }
    default: throw LinkError("a message with an unknown kind of shape");
    }
}
template <> Primitive Reader::get<Primitive>() {
    Primitive p;
    p.shape = get<Shape>();
    p.material = get<std::uint32_t>();
    p.vertex_normals = raw<std::int32_t>();
    p.index = get<std::uint32_t>();
    p.line = get<std::uint32_t>();
    return p;
}
template <> Material Reader::get<Material>() {
    Material m;
    m.color = get<Vec3>(), m.diffuse = get<double>(), m.specular_color = get<Vec3>(), m.specular = get<double>();
    m.shininess = get<double>(), m.transmittance = get<double>(), m.ior = get<double>();
    if (get<bool>()) {
        Checker checker;
        checker.color_a = get<Vec3>(), checker.color_b = get<Vec3>(), checker.size = get<double>();
        m.checker = checker;
    }
    return m;
}
template <> PointLight Reader::get<PointLight>() {
    PointLight light;
    light.position = get<Vec3>();
    light.color = get<Vec3>();
    return light;
}
template <> Aabb Reader::get<Aabb>() {
    Aabb box;
    box.min = get<Vec3>(), box.max = get<Vec3>();
    return box;
}
template <> std::vector<Aabb> Reader::get<std::vector<Aabb>>() {
    std::vector<Aabb> boxes(count(48));
    for (Aabb& box : boxes) box = get<Aabb>();
    return boxes;
}
template <> BvhTree Reader::get<BvhTree>() {
    // Only sizes are checked here; whether it is a hierarchy over the boxes, the receiver checks (bvh_tree_error).
    BvhTree tree;
    tree.nodes.resize(count(56));
    for (BvhNode& node : tree.nodes) node.bounds = get<Aabb>(), node.first = get<std::uint32_t>(), node.count = get<std::uint32_t>();
    tree.order.resize(count(4));
    for (std::uint32_t& index : tree.order) index = get<std::uint32_t>();
    return tree;
}
template <> std::optional<double> Reader::get<std::optional<double>>() {
    if (!get<bool>()) return std::nullopt;
    return get<double>();
}
template <> AreaLight Reader::get<AreaLight>() {
    AreaLight light;
    light.center = get<Vec3>(), light.color = get<Vec3>(), light.edge_u = get<Vec3>(), light.edge_v = get<Vec3>();
    light.samples = get<int>(), light.first_number = get<std::uint32_t>();
    // As the scene loader allows: a light's points are made in one go.
    if (light.samples < 1 || light.samples > 4096) throw LinkError("an area light with a bad sample count");
    return light;
}
template <> std::vector<PointLight> Reader::get<std::vector<PointLight>>() {
    std::vector<PointLight> lights(count(48));
    for (PointLight& light : lights) light = get<PointLight>();
    return lights;
}
template <> RenderSettings Reader::get<RenderSettings>() {
    RenderSettings s;
    s.stage = get<int>(), s.max_depth = get<int>(), s.min_weight = get<double>();
    s.max_rays_per_pixel = get<std::uint32_t>();
    s.samples_per_pixel = get<int>();
    if (s.samples_per_pixel < 0 || s.samples_per_pixel > (1 << 16)) throw LinkError("settings with a bad sample count");
    return s;
}
template <> RayStats Reader::get<RayStats>() {
    RayStats s;
    s.eye = get<std::uint64_t>(), s.shadow = get<std::uint64_t>(), s.reflected = get<std::uint64_t>();
    s.refracted = get<std::uint64_t>(), s.pixels_cut_short = get<std::uint64_t>();
    return s;
}
template <> TracerState Reader::get<TracerState>() {
    TracerState s;
    s.stats = get<RayStats>();
    s.path_weight = get<Vec3>();
    s.pixel_rays = get<std::uint32_t>();
    s.pixel_cut_short = get<bool>();
    s.sample.x = get<int>(), s.sample.y = get<int>(), s.sample.index = get<int>();
    return s;
}
template <> SceneData Reader::get<SceneData>() {
    SceneData d;
    d.camera = get<Camera>(), d.background = get<Vec3>(), d.ambient = get<Vec3>();
    d.lights = get<std::vector<PointLight>>();
    d.area_lights.resize(count(108));
    for (AreaLight& light : d.area_lights) light = get<AreaLight>();
    d.materials.resize(count(81));
    for (Material& material : d.materials) material = get<Material>();
    d.primitives.resize(count(41));
    for (Primitive& primitive : d.primitives) primitive = get<Primitive>();
    d.vertex_normals.resize(count(72));
    for (VertexNormals& normals : d.vertex_normals) normals = {get<Vec3>(), get<Vec3>(), get<Vec3>()};
    d.max_depth = get<int>(), d.samples_per_pixel = get<int>();
    const int acceleration = get<int>();
    if (acceleration < 0 || acceleration > static_cast<int>(Acceleration::bvh)) throw LinkError("a scene with a bad acceleration");
    d.acceleration = static_cast<Acceleration>(acceleration);
    if (get<bool>()) {
        std::array<SkyboxFace, 6> faces;
        for (SkyboxFace& face : faces) {
            face.width = get<int>(), face.height = get<int>();
            const std::string rgb = get<std::string>();
            face.rgb.assign(rgb.begin(), rgb.end());
        }
        try { // the skybox checks each face's size against its values
            d.skybox = std::make_shared<const Skybox>(std::move(faces));
        } catch (const std::invalid_argument&) {
            throw LinkError("a skybox face with a bad size");
        }
    }
    return d;
}
template <> std::optional<Hit> Reader::get<std::optional<Hit>>() {
    if (!get<bool>()) return std::nullopt;
    return get<Hit>();
}
template <> std::optional<Vec3> Reader::get<std::optional<Vec3>>() {
    if (!get<bool>()) return std::nullopt;
    return get<Vec3>();
}

} // namespace whitted::link
