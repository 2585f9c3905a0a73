// The bytes that cross between the checker and the worker: frames on a pipe,
// and the encoding of the framework's values inside them.
//
// Why: grading runs the student's lab code in a worker process and the tests
// in a checker process (lab_link.hpp). Only values cross between them, so both
// sides must agree on one plain encoding, and the side that reads what the
// other wrote must treat every byte as hostile: a frame has a size cap, a
// reader never reads past its frame, and a bad frame is a LinkError, never a
// crash. Doubles travel as their 8 bytes, so answers are bit for bit those
// the lab code computed.
#pragma once

#include "channel.hpp"
#include "whitted/camera.hpp"
#include "whitted/hit.hpp"
#include "whitted/interval.hpp"
#include "whitted/scene.hpp"
#include "whitted/tracer.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace whitted::link {

/// The other side broke the protocol, closed the link or sent too much.
struct LinkError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

enum class FrameType : std::uint8_t { call = 1, reply = 2, exception = 3, scene = 4, bye = 5 };

struct Frame {
    FrameType type = FrameType::bye;
    std::vector<std::byte> payload;
};

/// Writes one frame (waiting while the channel is full). Throws LinkError when the other side is gone.
void write_frame(Channel& channel, FrameType type, const std::vector<std::byte>& payload);

/// Reads frames from a channel, as many bytes at a time as it holds.
class FrameReader {
  public:
    FrameReader(Channel& channel, std::size_t max_bytes) : channel_(channel), max_bytes_(max_bytes) {}
    /// The next frame, of at most max_bytes. Throws LinkError on end of file, a
    /// bad type or an oversized frame.
    Frame next();

  private:
    void fill(std::size_t bytes); // until `bytes` bytes are buffered
    Channel& channel_;
    std::size_t max_bytes_;
    std::vector<std::byte> buffer_; // bytes [start_, end_) are received and not yet read
    std::size_t start_ = 0, end_ = 0;
};

/// Appends values to a payload.
class Writer {
  public:
    template <class T>
        requires std::is_arithmetic_v<T> || std::is_enum_v<T>
    void raw(T value) {
        const std::size_t at = bytes_.size();
        bytes_.resize(at + sizeof(T));
        std::memcpy(bytes_.data() + at, &value, sizeof(T));
    }
    void put(double value) { raw(value); }
    void put(int value) { raw(static_cast<std::int32_t>(value)); }
    void put(std::uint32_t value) { raw(value); }
    void put(std::uint64_t value) { raw(value); }
    void put(bool value) { raw(static_cast<std::uint8_t>(value ? 1 : 0)); }
    void put(const Vec2& v) { raw(v.x), raw(v.y); }
    void put(const Vec3& v) { raw(v.x), raw(v.y), raw(v.z); }
    void put(const std::string& text);
    void put(const Ray& ray);
    void put(const Interval& interval);
    void put(const Hit& hit);
    void put(const Camera& camera);
    void put(const Shape& shape);
    void put(const Primitive& primitive);
    void put(const Material& material);
    void put(const PointLight& light);
    void put(const AreaLight& light);
    void put(const Aabb& box);
    void put(const BvhTree& tree);
    void put(const RenderSettings& settings);
    void put(const RayStats& stats);
    void put(const TracerState& state);
    void put(const SceneData& data);
    template <class T>
    void put(const std::optional<T>& value) {
        put(value.has_value());
        if (value) put(*value);
    }
    template <class T>
    void put_all(const T& values) {
        put(static_cast<std::uint64_t>(values.size()));
        for (const auto& value : values) put(value);
    }

    std::vector<std::byte>& bytes() { return bytes_; }

  private:
    std::vector<std::byte> bytes_;
};

/// Reads values back from a payload; reading past its end is a LinkError.
class Reader {
  public:
    explicit Reader(const std::vector<std::byte>& bytes) : bytes_(bytes) {}

    template <class T>
        requires std::is_arithmetic_v<T> || std::is_enum_v<T>
    T raw() {
        if (bytes_.size() - position_ < sizeof(T)) throw LinkError("a message ended too early");
        T value;
        std::memcpy(&value, bytes_.data() + position_, sizeof(T));
        position_ += sizeof(T);
        return value;
    }
    /// The value of type T that comes next.
    template <class T>
    T get();
    /// A count of items that each take at least `item_bytes`, checked against what is left.
    std::size_t count(std::size_t item_bytes);
    bool at_end() const { return position_ == bytes_.size(); }

  private:
    const std::vector<std::byte>& bytes_;
    std::size_t position_ = 0;
};

template <> inline double Reader::get<double>() { return raw<double>(); }
template <> inline int Reader::get<int>() { return raw<std::int32_t>(); }
template <> inline std::uint32_t Reader::get<std::uint32_t>() { return raw<std::uint32_t>(); }
template <> inline std::uint64_t Reader::get<std::uint64_t>() { return raw<std::uint64_t>(); }
template <> bool Reader::get<bool>();
template <> Vec2 Reader::get<Vec2>();
template <> Vec3 Reader::get<Vec3>();
template <> std::string Reader::get<std::string>();
template <> Ray Reader::get<Ray>();
template <> Interval Reader::get<Interval>();
template <> Hit Reader::get<Hit>();
template <> Camera Reader::get<Camera>();
template <> Shape Reader::get<Shape>();
template <> Primitive Reader::get<Primitive>();
template <> Material Reader::get<Material>();
template <> PointLight Reader::get<PointLight>();
template <> AreaLight Reader::get<AreaLight>();
template <> Aabb Reader::get<Aabb>();
template <> BvhTree Reader::get<BvhTree>();
template <> std::vector<Aabb> Reader::get<std::vector<Aabb>>();
template <> std::optional<double> Reader::get<std::optional<double>>();
template <> std::vector<PointLight> Reader::get<std::vector<PointLight>>();
template <> RenderSettings Reader::get<RenderSettings>();
template <> RayStats Reader::get<RayStats>();
template <> TracerState Reader::get<TracerState>();
template <> SceneData Reader::get<SceneData>();
template <> std::optional<Hit> Reader::get<std::optional<Hit>>();
template <> std::optional<Vec3> Reader::get<std::optional<Vec3>>();

} // namespace whitted::link
