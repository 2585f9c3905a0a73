#include "lab_link.hpp"

#include "printable.hpp"
#include "whitted/lab_table.hpp"
#include "whitted/labs.hpp"
#include "whitted/not_implemented.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <iterator>
#include <thread>

namespace whitted::link {
namespace {

Link* g_current = nullptr; // set once by the program's main

// A frame from the worker is a few hundred bytes; a scene for the worker may be large.
constexpr std::size_t kMaxFromWorker = std::size_t{1} << 25; // 32 MiB: lab 10 sends back whole trees (56 bytes a node)
constexpr std::size_t kMaxFromChecker = std::size_t{1} << 28;
constexpr int kMaxNesting = 4000;       // calls inside calls, both ways together
constexpr std::size_t kScenesKept = 8;  // scenes the worker holds at once
constexpr std::size_t kMaxMessage = 2000;
constexpr std::size_t kMostAnswersAhead = 8; // with one call to the worker
constexpr std::size_t kCallHeaderBytes = 3;  // [op: 2 bytes][answers ahead: 1 byte] of a call from the checker

enum class ExceptionKind : std::uint8_t { not_implemented = 1, std_exception = 2, unknown = 3, refused = 4 };

bool takes_tracer(Op op) {
    switch (op) {
    case Op::is_lit: case Op::lambert: case Op::blinn_phong: case Op::reflection: case Op::refraction:
    case Op::fresnel_blend: case Op::light_samples: case Op::tracer_trace: case Op::tracer_trace_sample:
    case Op::tracer_trace_pixels: return true;
    default: return false;
    }
}

std::vector<std::byte> exception_payload(ExceptionKind kind, const std::string& message) {
    Writer out;
    out.raw(kind);
    out.put(message.substr(0, kMaxMessage));
    return std::move(out.bytes());
}

// Byte blobs cross as the wire's strings.
std::vector<std::byte> bytes_of(const std::string& text) {
    const auto* first = reinterpret_cast<const std::byte*>(text.data());
    return {first, first + text.size()};
}
std::string text_of(const std::vector<std::byte>& bytes) { return {reinterpret_cast<const char*>(bytes.data()), bytes.size()}; }

// The answers ahead of a call from the checker (Call::answers_ahead()).
std::vector<AnswerAhead> read_answers_ahead(Reader& in) {
    const auto count = in.raw<std::uint8_t>();
    if (count > kMostAnswersAhead) throw LinkError("a call with too many answers ahead");
    std::vector<AnswerAhead> answers(count);
    for (AnswerAhead& answer : answers) {
        answer.call = bytes_of(in.get<std::string>());
        answer.reply = bytes_of(in.get<std::string>());
    }
    return answers;
}

} // namespace

// The name of each Op's function, in the enum's order.
constexpr std::array<std::string_view, kLastOp + 1> kFunctionNames{
    "?", "primary_ray", "intersect_sphere", "intersect_plane", "intersect_triangle", "closest_hit",
    "Scene::closest_hit", "Scene::occluded", "spawn_ray", "is_lit", "lambert", "blinn_phong",
    "mirror_direction", "reflection", "refracted_direction", "refraction", "fresnel_reflectance",
    "fresnel_blend", "stratified_sample", "pixel_color", "point_on_light", "light_samples",
    "concentric_disk", "thin_lens_ray", "box_entry", "build_bvh", "bvh_closest_hit", "bvh_occluded",
    "Scene::lab_bvh", "intersect", "Tracer::trace", "Tracer::trace_sample",
    "stratified_sample", // stratified_cell: the student's code called stratified_sample()
    "thin_lens_ray",      // thin_lens_rays: the checker's render called it
    "Tracer::trace_pixels"};
constexpr bool every_op_named() {
    for (std::string_view name : kFunctionNames)
        if (name.empty()) return false;
    return true;
}
static_assert(every_op_named(), "every Op of lab_link.hpp needs its function's name in kFunctionNames, in the enum's order");

std::string_view function_of(Op op) {
    const int index = static_cast<int>(op);
    return index >= 1 && index <= kLastOp ? kFunctionNames[static_cast<std::size_t>(index)] : "?";
}

int lab_of(Op op) {
    // Each function's lab from the lab table, looked up once; the scene's two queries are
    // made of lab 1's code (closest_hit and the intersections).
    static const std::array<int, kLastOp + 1> labs = [] {
        std::array<int, kLastOp + 1> found{};
        for (int index = 1; index <= kLastOp; ++index)
            for (const LabInfo& lab : kLabs)
                for (const std::string_view function : lab_functions(lab))
                    if (function == function_of(static_cast<Op>(index))) found[static_cast<std::size_t>(index)] = lab.number;
        found[static_cast<std::size_t>(Op::scene_closest_hit)] = found[static_cast<std::size_t>(Op::scene_occluded)] =
            stage_number(Stage::ray_casting);
        found[static_cast<std::size_t>(Op::scene_lab_bvh)] = stage_number(Stage::bvh);
        found[static_cast<std::size_t>(Op::intersect_shape)] = stage_number(Stage::ray_casting);
        return found;
    }();
    const int index = static_cast<int>(op);
    return index >= 1 && index <= kLastOp ? labs[static_cast<std::size_t>(index)] : 0;
}

std::string name_of(Op op) { return std::string(function_of(op)) + "()"; }

std::string refused_inside(Op caller, Op callee) {
    switch (caller) {
    case Op::box_entry:
    case Op::build_bvh: return name_of(caller) + " needs no other lab's code";
    case Op::bvh_closest_hit:
    case Op::bvh_occluded:
        if (callee == Op::intersect_sphere || callee == Op::intersect_plane || callee == Op::intersect_triangle ||
            callee == Op::intersect_shape || callee == Op::scene_lab_bvh)
            return "";
        return "a walk of the BVH tests the primitives of the leaves it reaches one by one, with intersect()";
    default: return "";
    }
}

std::string lab_call_name(Op op) {
    const int number = lab_of(op);
    const bool scene_query = op == Op::scene_closest_hit || op == Op::scene_occluded;
    const std::string function = scene_query ? "closest_hit()" : name_of(op);
    return number == 0 ? function : function + " (labs/" + std::string(lab(number).stem) + ".cpp)";
}

Link::Link(Role role, const ChannelFds& fds, LabSet remote_labs)
    : role_(role), channel_(fds, role == Role::checker),
      in_(channel_, role == Role::checker ? kMaxFromWorker : kMaxFromChecker),
      remote_labs_(remote_labs) {}

Link& Link::current() {
    if (!g_current) throw std::logic_error("this program has no link to a grading worker or checker");
    return *g_current;
}

void Link::set_current(Link* link) { g_current = link; }

void Link::fail(const std::string& reason) {
    if (broken_.empty()) broken_ = reason;
    throw LinkError(reason);
}

// ---- calls out --------------------------------------------------------------------------

Link::Call::Call(Link& link, Op op) : link_(link), lock_(link.mutex_), op_(op) {
    if (!link_.broken_.empty()) throw LinkError(link_.broken_);
    args_.raw(static_cast<std::uint16_t>(op));
    if (link_.role_ == Role::checker) args_.raw(std::uint8_t{0}); // answers ahead: none unless answers_ahead() says
    link_.calls_out_.push_back(op);
}

Link::Call::~Call() {
    link_.calls_out_.pop_back();
    link_.active_.resize(link_.active_.size() - pushed_tracers_);
    link_.active_scenes_.resize(link_.active_scenes_.size() - pushed_scenes_);
}

void Link::Call::tracer(const Tracer& tracer) {
    tracer_ = &tracer;
    if (link_.role_ == Role::checker) {
        if (tracer.records_tree()) throw std::logic_error("ray trees are not recorded across the grading link");
        const std::uint64_t handle = link_.next_handle_++;
        args_.put(handle);
        scene(tracer.scene());
        link_.active_.push_back({handle, &tracer});
        ++pushed_tracers_;
        args_.put(tracer.settings());
        // One graded lab here: the worker sends its tracer's recursion back (the rest of the labs are here).
        args_.raw(static_cast<std::uint8_t>(std::popcount(link_.remote_labs_) == 1));
    } else {
        const auto active = std::find_if(link_.active_.rbegin(), link_.active_.rend(),
                                         [&](const ActiveTracer& a) { return a.tracer == &tracer; });
        if (active == link_.active_.rend())
            throw std::logic_error(name_of(op_) + " was given a Tracer that the framework did not make: pass on "
                                   "the tracer your function received");
        args_.put(active->handle);
    }
    args_.put(tracer.state());
}

void Link::Call::scene(const Scene& scene) {
    args_.put(link_.serial_of(scene));
    if (link_.role_ == Role::checker) {
        link_.active_scenes_.push_back(&scene);
        ++pushed_scenes_;
    }
}

void Link::Call::answers_ahead(const std::vector<AnswerAhead>& answers) {
    if (answers.empty()) return;
    if (link_.role_ != Role::checker || args_.bytes().size() != kCallHeaderBytes || answers.size() > kMostAnswersAhead)
        throw std::logic_error("answers ahead go from the checker, before a call's arguments, at most " +
                               std::to_string(kMostAnswersAhead));
    args_.bytes()[2] = static_cast<std::byte>(answers.size());
    for (const AnswerAhead& answer : answers) {
        args_.put(text_of(answer.call));
        args_.put(text_of(answer.reply));
    }
}

void Link::Call::primitives(std::span<const Primitive> primitives) { args_.put_all(primitives); }

std::uint64_t Link::serial_of(const Scene& scene) {
    if (role_ == Role::checker) {
        send_scene(scene);
        return scene.serial();
    }
    for (const auto& [serial, held] : scenes_)
        if (held.get() == &scene) return serial;
    throw std::logic_error("lab code may only use the scene of the tracer it was given");
}

void Link::send_scene(const Scene& scene) {
    const std::uint64_t serial = scene.serial();
    const auto held = std::find(sent_scenes_.begin(), sent_scenes_.end(), serial);
    if (held != sent_scenes_.end()) {
        sent_scenes_.erase(held);
        sent_scenes_.push_back(serial); // most recently used last
        return;
    }
    std::uint64_t evict = 0;
    if (sent_scenes_.size() >= kScenesKept) {
        for (auto it = sent_scenes_.begin(); it != sent_scenes_.end(); ++it) {
            const bool in_use = std::any_of(active_scenes_.begin(), active_scenes_.end(),
                                            [&](const Scene* s) { return s->serial() == *it; });
            if (!in_use) {
                evict = *it;
                sent_scenes_.erase(it);
                break;
            }
        }
    }
    Writer out;
    out.put(serial);
    out.put(evict);
    out.put(scene.source_data());
    write_frame(channel_, FrameType::scene, out.bytes());
    sent_scenes_.push_back(serial);
}

Reader& Link::Call::send() {
    ++link_.depth_;
    struct Unnest {
        int& depth;
        ~Unnest() { --depth; }
    } unnest{link_.depth_};
    try {
        if (link_.depth_ > kMaxNesting) link_.fail("calls nested more than " + std::to_string(kMaxNesting) + " deep");
        if (const AnswerAhead* ahead = link_.answered_ahead(args_.bytes(), tracer_ != nullptr)) {
            reply_ = Frame{FrameType::reply, ahead->reply};
        } else {
            write_frame(link_.channel_, FrameType::call, args_.bytes());
            reply_ = link_.wait_for_reply();
        }
    } catch (const LinkError& e) {
        if (link_.role_ == Role::checker) {
            // The innermost call catches the break first: the call the worker was running when it died (none to
            // name for a block of pixels, which runs every lab's code).
            if (link_.broken_.empty() && !is_recursion(op_)) link_.broken_during_ = lab_call_name(op_);
            link_.fail(e.what());
        }
        throw;
    }
    reader_ = std::make_unique<Reader>(reply_.payload);
    if (reply_.type == FrameType::exception) {
        const auto kind = reader_->raw<ExceptionKind>();
        std::string message = reader_->get<std::string>();
        if (link_.role_ == Role::checker) message = detail::escaped_bytes(message.substr(0, kMaxMessage), true);
        switch (kind) {
        case ExceptionKind::not_implemented: throw NotImplemented(message);
        case ExceptionKind::std_exception: throw RemoteError(message);
        case ExceptionKind::unknown: throw RemoteUnknownException{};
        case ExceptionKind::refused:
            if (link_.role_ == Role::worker) throw LinkError(message);
            throw RemoteError(message);
        default: link_.fail("a reply with an unknown kind of exception");
        }
    }
    try {
        if (tracer_) tracer_->restore(reader_->get<TracerState>());
    } catch (const LinkError& e) {
        if (link_.role_ == Role::checker) link_.fail(e.what());
        throw;
    }
    return *reader_;
}

void Link::Call::done() {
    if (!reader_->at_end()) {
        if (link_.role_ == Role::checker) link_.fail("a reply to " + name_of(op_) + " longer than its result");
        throw LinkError("a reply longer than its result");
    }
}

Frame Link::wait_for_reply() {
    for (;;) {
        Frame frame = in_.next();
        switch (frame.type) {
        case FrameType::reply:
        case FrameType::exception: return frame;
        case FrameType::call:
            serve(frame);
            // A call the checker refused broke the link: the call it waits on fails now, not when the worker answers.
            if (role_ == Role::checker && !broken_.empty()) throw LinkError(broken_);
            break;
        case FrameType::scene:
            if (role_ == Role::checker) fail("the worker sent a scene");
            serve(frame);
            break;
        case FrameType::bye: fail("the other side said goodbye in the middle of a call");
        }
    }
}

const AnswerAhead* Link::answered_ahead(const std::vector<std::byte>& call, bool with_tracer) const {
    if (role_ != Role::worker || with_tracer || answers_ahead_.empty()) return nullptr;
    for (const AnswerAhead& answer : answers_ahead_.back())
        if (answer.call == call) return &answer;
    return nullptr;
}

// ---- calls in ---------------------------------------------------------------------------

void Link::serve_until_closed() {
    std::lock_guard lock(mutex_);
    for (;;) {
        Frame frame;
        try {
            frame = in_.next();
        } catch (const LinkError&) {
            return; // closed
        }
        if (frame.type == FrameType::bye) return;
        if (frame.type != FrameType::call && frame.type != FrameType::scene)
            throw LinkError("a reply that answers no call");
        serve(frame);
    }
}

void Link::say_goodbye() {
    std::lock_guard lock(mutex_);
    try {
        // The last reply may have been followed by writing over the shared memory: that breaks the link too.
        channel_.check_positions();
    } catch (const LinkError& e) {
        if (broken_.empty()) broken_ = e.what();
        return;
    }
    try {
        write_frame(channel_, FrameType::bye, {});
    } catch (const LinkError&) {
        // the other side is gone already
    }
}

bool Link::allowed(Op op, const Tracer* tracer) const {
    if (is_recursion(op)) return tracer != nullptr; // the framework's, on a tracer this checker lent
    const int lab = lab_of(op);
    if (lab == 0 || (remote_labs_ & lab_bit(lab))) return false; // its code is over there
    int graded = 1;
    while (graded <= kLabCount && !(remote_labs_ & lab_bit(graded))) ++graded;
    if (lab < graded) return true;                                  // an earlier lab: the student's code may use it
    return tracer != nullptr && lab <= tracer->settings().stage;   // a later lab, as the render's stage asks
}

void Link::serve(const Frame& frame) {
    Reader in(frame.payload);
    if (frame.type == FrameType::scene) { // worker only
        const auto serial = in.get<std::uint64_t>();
        const auto evict = in.get<std::uint64_t>();
        SceneData data = in.get<SceneData>();
        if (evict) scenes_.erase(evict);
        scenes_[serial] = std::make_unique<Scene>(std::move(data));
        return;
    }
    const auto op = static_cast<Op>(in.raw<std::uint16_t>());
    const std::size_t tracers_before = active_.size(), locals_before = local_tracers_.size();
    if (role_ == Role::worker) answers_ahead_.push_back(read_answers_ahead(in));
    calls_in_.push_back(op);
    Writer out;
    ExceptionKind kind{};
    std::string message;
    ++depth_;
    try {
        if (lab_of(op) == 0 && !is_recursion(op)) fail("a call of unknown function " + std::to_string(static_cast<int>(op)));
        // The shortcuts go one way each: cells from the checker's lab 7, a pixel's lens rays from the worker's lab 9,
        // blocks of pixels from a worker that holds every lab.
        if ((op == Op::stratified_cell && role_ == Role::worker) ||
            ((op == Op::thin_lens_rays || op == Op::tracer_trace_pixels) && role_ == Role::checker))
            fail("a call of " + name_of(op) + " that only the other side makes");
        if (depth_ > kMaxNesting) fail("calls nested more than " + std::to_string(kMaxNesting) + " deep");
        if (role_ == Role::checker && op != Op::scene_lab_bvh && !takes_tracer(op) && !allowed(op, nullptr))
            fail("the graded lab's code called " + name_of(op) + ", which grading does not answer for it");
        if (role_ == Role::checker && !calls_out_.empty())
            if (const std::string why = refused_inside(calls_out_.back(), op); !why.empty())
                fail("your " + name_of(calls_out_.back()) + " called " + name_of(op) +
                     ", which grading does not answer inside it: " + why);
        serve_op(*this, op, in, out);
    } catch (const NotImplemented& e) {
        kind = ExceptionKind::not_implemented, message = e.what();
    } catch (const LinkError& e) {
        kind = ExceptionKind::refused, message = e.what();
    } catch (const std::exception& e) {
        kind = ExceptionKind::std_exception, message = e.what();
    } catch (...) {
        kind = ExceptionKind::unknown;
    }
    --depth_;
    calls_in_.pop_back();
    if (role_ == Role::worker) answers_ahead_.pop_back();
    active_.resize(tracers_before);
    local_tracers_.resize(locals_before);
    if (kind == ExceptionKind{}) write_frame(channel_, FrameType::reply, out.bytes());
    else write_frame(channel_, FrameType::exception, exception_payload(kind, message));
}

namespace {

// A worker tracer's recursion, run by the checker on the tracer it lent (Call::tracer() encodes which).
class RecursionInChecker final : public TraceForwarding {
  public:
    Color trace(const Tracer& tracer, const Ray& ray, int depth, RayKind kind, const Color& weight) const override {
        Link::Call call(Link::current(), Op::tracer_trace);
        call.tracer(tracer);
        call.args().put(ray), call.args().put(depth), call.args().raw(static_cast<std::uint8_t>(kind)), call.args().put(weight);
        return call.result<Color>();
    }
    Color trace_sample(const Tracer& tracer, const PixelSample& sample, double x, double y) const override {
        Link::Call call(Link::current(), Op::tracer_trace_sample);
        call.tracer(tracer);
        call.args().put(sample.x), call.args().put(sample.y), call.args().put(sample.index), call.args().put(x), call.args().put(y);
        return call.result<Color>();
    }
};
const RecursionInChecker kRecursionInChecker;

} // namespace

const Tracer& Link::incoming_tracer(Reader& in, Op op) {
    const auto handle = in.get<std::uint64_t>();
    if (role_ == Role::checker) {
        const auto state = in.get<TracerState>();
        const auto active = std::find_if(active_.rbegin(), active_.rend(),
                                         [&](const ActiveTracer& a) { return a.handle == handle; });
        if (active == active_.rend()) fail("a call with a tracer that is not in use");
        if (!allowed(op, active->tracer))
            fail("the graded lab's code called " + name_of(op) + ", which grading does not answer for it");
        active->tracer->restore(state);
        return *active->tracer;
    }
    const auto serial = in.get<std::uint64_t>();
    const RenderSettings settings = in.get<RenderSettings>();
    const bool forward = in.raw<std::uint8_t>() != 0;
    const auto state = in.get<TracerState>();
    const auto held = scenes_.find(serial);
    if (held == scenes_.end()) throw LinkError("a call with a scene this worker does not hold");
    auto local = std::make_unique<LocalTracer>();
    local->settings = settings;
    local->tracer = std::make_unique<Tracer>(*held->second, local->settings, local->stats);
    local->tracer->restore(state);
    if (forward) local->tracer->forward_to(&kRecursionInChecker);
    active_.push_back({handle, local->tracer.get()});
    local_tracers_.push_back(std::move(local));
    return *local_tracers_.back()->tracer;
}

const Scene& Link::incoming_scene(Reader& in) {
    const auto serial = in.get<std::uint64_t>();
    if (role_ == Role::checker) {
        for (const Scene* scene : active_scenes_)
            if (scene->serial() == serial) return *scene;
        fail("a call with a scene that is not in use");
    }
    const auto held = scenes_.find(serial);
    if (held == scenes_.end()) throw LinkError("a call with a scene this worker does not hold");
    return *held->second;
}

std::optional<StratifiedCell> Link::stratified_cell(int index, int count) {
    std::lock_guard lock(mutex_); // the student's code may call from threads of its own
    // Where the checker would refuse stratified_sample(), the call goes over and is refused there.
    if (!calls_in_.empty() && !refused_inside(calls_in_.back(), Op::stratified_cell).empty()) return std::nullopt;
    const auto known = cells_.find({index, count});
    if (known != cells_.end()) return known->second;
    Call call(*this, Op::stratified_cell);
    call.args().put(index), call.args().put(count);
    Reader& in = call.send();
    std::optional<StratifiedCell> cell;
    if (in.get<bool>()) {
        cell.emplace();
        cell->cell = in.get<Vec2>();
        cell->grid = in.get<Vec2>();
    }
    call.done();
    cells_.emplace(std::pair{index, count}, cell);
    return cell;
}

std::optional<StratifiedCell> stratified_cell_of(int index, int count) {
    // (cell + u) / grid at u = 0 and u = 1/2: grid = (1/2) / their difference, cell = grid x the first.
    const Vec2 low = stratified_sample(index, count, Vec2(0.0));
    const Vec2 middle = stratified_sample(index, count, Vec2(0.5));
    StratifiedCell found;
    found.grid = Vec2(std::round(0.5 / (middle.x - low.x)), std::round(0.5 / (middle.y - low.y)));
    found.cell = Vec2(std::round(low.x * found.grid.x), std::round(low.y * found.grid.y));
    const double largest = 1u << 24;
    if (!(found.grid.x >= 1.0 && found.grid.x <= largest && found.grid.y >= 1.0 && found.grid.y <= largest &&
          std::abs(found.cell.x) <= largest && std::abs(found.cell.y) <= largest))
        return std::nullopt;
    // The worker's answers must be this program's to the last bit: checked across [0, 1), ends included.
    constexpr double kNumbers[] = {0.0, 0.5, 0.1, 0.3333333333333333, 0.7071067811865476, 0.123456789,
                                   0.987654321, 0.2718281828459045, 0.6180339887498949, 0.9999999999999999};
    constexpr std::size_t kCount = std::size(kNumbers);
    for (std::size_t i = 0; i < kCount; ++i) {
        const Vec2 u(kNumbers[i], kNumbers[(i + 3) % kCount]);
        const Vec2 expected = stratified_sample(index, count, u);
        const Vec2 computed = found.sample(u);
        if (computed.x != expected.x || computed.y != expected.y) return std::nullopt;
    }
    return found;
}

bool LensRaysAhead::Query::operator==(const Query& other) const {
    return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(other.x) &&
           std::bit_cast<std::uint64_t>(y) == std::bit_cast<std::uint64_t>(other.y) &&
           std::bit_cast<std::uint64_t>(lens_u.x) == std::bit_cast<std::uint64_t>(other.lens_u.x) &&
           std::bit_cast<std::uint64_t>(lens_u.y) == std::bit_cast<std::uint64_t>(other.lens_u.y);
}

std::vector<LensRaysAhead::Query> pixel_samples_from(double x, double y, Vec2 lens_u) {
    constexpr int kMostSamples = 1024;
    if (!(std::abs(x) < 1e9 && std::abs(y) < 1e9)) return {};
    const int px = static_cast<int>(std::floor(x)), py = static_cast<int>(std::floor(y));
    auto sample = [&](int index) { return PixelSample{px, py, index}; };
    int k = 0;
    while (k < kMostSamples && sample_numbers(sample(k), SampleUse::lens) != lens_u) ++k;
    if (k == kMostSamples) return {};
    auto query = [&](int index, int count) {
        const Vec2 place = stratified_sample(index, count, sample_numbers(sample(index), SampleUse::pixel));
        return LensRaysAhead::Query{px + place.x, py + place.y, sample_numbers(sample(index), SampleUse::lens)};
    };
    const LensRaysAhead::Query asked{x, y, lens_u};
    const Vec2 pixel_numbers = sample_numbers(sample(k), SampleUse::pixel); // the count is the unknown: found from x, y
    for (int count = k + 1; count <= kMostSamples; ++count) {
        const Vec2 place = stratified_sample(k, count, pixel_numbers);
        if (LensRaysAhead::Query{px + place.x, py + place.y, lens_u} != asked) continue;
        std::vector<LensRaysAhead::Query> queries;
        for (int index = k; index < count; ++index) queries.push_back(query(index, count));
        return queries;
    }
    return {};
}

std::optional<Ray> Link::thin_lens_ray_ahead(const Camera& camera, double x, double y, Vec2 lens_u) {
    // Only where lab 9 alone is the worker's: the guess asks this program's lab 7, which must be the reference.
    if (remote_labs_ != lab_bit(stage_number(Stage::depth_of_field))) return std::nullopt;
    std::lock_guard lock(mutex_);
    Writer camera_bytes;
    camera_bytes.put(camera);
    // A render's threads each trace pixels of their own: a batch a thread.
    LensRaysAhead& ahead = lens_rays_[std::this_thread::get_id()];
    const LensRaysAhead::Query asked{x, y, lens_u};
    const bool expected = ahead.next < ahead.queries.size() && ahead.queries[ahead.next] == asked &&
                          ahead.camera == camera_bytes.bytes();
    if (expected && ahead.next < ahead.rays.size()) return ahead.rays[ahead.next++];
    ahead = {};
    if (expected) return std::nullopt; // the query that ended its batch by throwing: asked alone, it throws here
    std::vector<LensRaysAhead::Query> queries = pixel_samples_from(x, y, lens_u);
    if (queries.size() < 2) return std::nullopt;
    Call call(*this, Op::thin_lens_rays);
    call.args().put(camera);
    call.args().put(static_cast<std::uint64_t>(queries.size()));
    for (const LensRaysAhead::Query& q : queries) call.args().put(q.x), call.args().put(q.y), call.args().put(q.lens_u);
    Reader& in = call.send();
    const std::size_t answered = in.count(48);
    if (answered > queries.size()) fail("a reply to thin_lens_ray() with more rays than were asked for");
    std::vector<Ray> rays(answered);
    for (Ray& ray : rays) ray = in.get<Ray>();
    call.done();
    if (rays.empty()) return std::nullopt; // the first threw: asked alone, it throws as it should
    ahead.camera = std::move(camera_bytes.bytes());
    ahead.queries = std::move(queries);
    ahead.rays = std::move(rays);
    ahead.next = 1;
    return ahead.rays.front();
}

void Link::check_hit(const Hit& hit, const Scene& scene) {
    if (role_ != Role::checker) return;
    if (hit.material >= scene.material_count() || hit.primitive >= scene.primitives().size())
        fail("a hit whose primitive (" + std::to_string(hit.primitive) + ") or material (" +
                                      std::to_string(hit.material) + ") is not in the scene");
}

} // namespace whitted::link
