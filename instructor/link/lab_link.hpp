// The link between a grading checker and a grading worker: lab functions
// called in one process and run in the other.
//
// Why: the tests, the reference labs and the expected values must live where
// the student's code is not (instructor/docs/grading.md, "Where the verdict lives"). So a
// checker program (the GoogleTest tests, the reference for every lab but the
// one graded, and for that lab `remote_NN.cpp`) calls the graded lab's
// functions over this link, and a worker program (the framework, the student's
// lab file, and `remote_NN.cpp` for every other lab) runs them. Lab code calls
// back into the other labs and the framework exactly as in one process: a call
// may nest calls in the other direction to any depth. Only values cross:
// scenes travel once, by their serial number; a Tracer crosses as a handle to
// the checker's tracer plus its state (ray counts, path weight, budget),
// synchronised both ways on every crossing.
//
// The checker owns every scene and tracer and answers the worker only with
// what lab k's code may use: functions of earlier labs, and those of later
// labs only through a tracer whose stage includes them. Everything the worker
// sends is checked (sizes, counts, indices) before the checker uses it; a
// worker that breaks the protocol breaks the link, and the checker fails the
// test (exit code 3), however the test handles exceptions.
#pragma once

#include "whitted/lab_table.hpp"
#include "wire.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace whitted::link {

/// Every function that can cross the link, with the lab it belongs to.
enum class Op : std::uint16_t {
    primary_ray = 1, intersect_sphere, intersect_plane, intersect_triangle, closest_hit,
    scene_closest_hit, scene_occluded, // Scene's two queries, made of lab 1's code
    spawn_ray, is_lit, lambert,
    blinn_phong,
    mirror_direction, reflection,
    refracted_direction, refraction,
    fresnel_reflectance, fresnel_blend,
    stratified_sample, pixel_color,
    point_on_light, light_samples,
    concentric_disk, thin_lens_ray,
    box_entry, build_bvh, bvh_closest_hit, bvh_occluded,
    scene_lab_bvh,   // the tree lab 10's walk uses: the checker's, so that both sides walk one tree
    intersect_shape, // the framework's own shapes (boxes, cones), tested where the worker cannot see how
    // The framework's recursion on a tracer the checker lent (TraceForwarding in whitted/tracer.hpp): run in the
    // checker, which holds every lab but the graded one, so that a lab's call crosses once.
    tracer_trace, tracer_trace_sample,
    // Lab 7's grid cell for (index, count), which the worker turns into stratified_sample()'s answers for
    // every u: lab 8's light_samples() asks it once per cell instead of once per light point (StratifiedCell).
    stratified_cell,
    // Lab 9's thin_lens_ray() for the samples of a pixel at once (LensRaysAhead).
    thin_lens_rays,
    // The framework's Tracer::trace_pixels() for a block of pixels, asked of a worker that holds every lab (the
    // integration tests): one crossing a block instead of an eye ray's, a hit's and a shading call's a pixel.
    tracer_trace_pixels,
};
constexpr int kLastOp = static_cast<int>(Op::tracer_trace_pixels);

/// Whether `op` is the framework's recursion (Tracer::trace, trace_sample, trace_pixels), which belongs to no lab.
constexpr bool is_recursion(Op op) {
    return op == Op::tracer_trace || op == Op::tracer_trace_sample || op == Op::tracer_trace_pixels;
}

/// The lab (1..kLabCount, from the lab table) whose code answers `op`; 0 for none.
int lab_of(Op op);
/// "blinn_phong()" for Op::blinn_phong, for messages.
std::string name_of(Op op);
/// "box_entry() (labs/10_bvh.cpp)": the lab function `op` runs and its file, for a student's
/// messages (the scene's queries run lab 1's closest_hit()).
std::string lab_call_name(Op op);

/// Why the checker does not answer `callee` while the graded lab's `caller`
/// runs in the worker, or "" when it does. Beyond the rule of which labs the
/// worker may use (Link's class comment), a function may not ask for what is
/// its own answer in disguise: lab 10's walks may only test primitives one by
/// one (lab 1's closest_hit() or the scene's queries would walk the checker's
/// tree), and box_entry() and build_bvh() need nothing of the other labs.
std::string refused_inside(Op caller, Op callee);

enum class Role {
    checker, // owns scenes and tracers; answers only what the policy allows
    worker,  // runs the student's code on what the checker sends
};

/// A set of labs as bits 1..kLabCount.
using LabSet = std::uint32_t;
static_assert(kLabCount < 32, "LabSet holds the labs as bits of 32");
constexpr LabSet lab_bit(int lab) { return LabSet{1} << lab; }
/// Labs 1..kLabCount, all of them.
constexpr LabSet every_lab() { return ((LabSet{1} << (kLabCount + 1)) - 1) & ~LabSet{1}; }

/// Where stratified_sample(index, count, u) puts every u: (cell + u) / grid, axis by axis, with cell and grid
/// whole numbers (the column and row of the sample's cell, and the grid's columns and rows).
///
/// Why: lab 8's light_samples() calls lab 7's stratified_sample() once per point of an area light, and a
/// worker has lab 7 only over the link: 1.2 million round trips in lab 8's image test. The checker sends the
/// cell once per (index, count), found from the reference's own answers and checked against them
/// (stratified_cell_of()), and the worker computes (cell + u) / grid exactly as the reference does, to the
/// last bit. Nothing of lab 7 is handed over that a call would not give: the worker asks only where the
/// graded lab may call stratified_sample(), and a worker of lab 7 never asks (its lab 7 is the student's).
struct StratifiedCell {
    Vec2 cell;
    Vec2 grid;
    /// The sample for u, as the reference computes it.
    Vec2 sample(Vec2 u) const { return Vec2((cell.x + u.x) / grid.x, (cell.y + u.y) / grid.y); }
};

/// The cell of stratified_sample(index, count, .) as this program's stratified_sample() answers, or nothing
/// when its answers are not (cell + u) / grid for whole numbers (then each sample must be asked for).
std::optional<StratifiedCell> stratified_cell_of(int index, int count);

/// Checker: the eye rays of the graded lab 9 for the samples of a pixel that come next, asked for in one call.
///
/// Why: a render with a thin lens asks thin_lens_ray() once per sample (307,200 times in lab 9's image test),
/// and each crossing is a round trip, slow on one CPU and slower still on a busy machine. When the asked
/// sample is sample k of pixel (px, py) as the checker's own pixel_color() and the framework's
/// sample_numbers() make them, the checker asks for samples k, k + 1, ... of that pixel in one call, and
/// answers the next calls from them while they are asked in that order with exactly those numbers; anything
/// else is one call each, as before. The worker runs the student's thin_lens_ray() on each in order, only
/// earlier; a wrong guess may ask for samples the render then does not trace, made of numbers lab 9 may ask for
/// itself (sample_numbers(), lab 7). One that throws ends the batch, and is asked alone. Only in lab 9's checker
/// (its lab 7 the reference), a batch per thread of the render.
struct LensRaysAhead {
    struct Query {
        double x, y;
        Vec2 lens_u;
        /// The same numbers, bit for bit (-0 is not 0: a lab's answer may tell them apart).
        bool operator==(const Query& other) const;
    };
    std::vector<std::byte> camera; // the camera's bytes on the wire
    std::vector<Query> queries;
    std::vector<Ray> rays;         // the answers of the first queries
    std::size_t next = 0;
};

/// The queries of samples k, k + 1, ... of pixel (px, py) as this program's pixel_color() asks them, when
/// (x, y, lens_u) is its sample k: x = px + stratified_sample(k, count, sample_numbers(sample, pixel)).x (y
/// alike) and lens_u = sample_numbers(sample, lens), the count found from them. Nothing when it is none.
std::vector<LensRaysAhead::Query> pixel_samples_from(double x, double y, Vec2 lens_u);

/// An answer the checker sends ahead with a call to the worker: a call of an earlier lab's pure function
/// (no tracer, no scene) as the worker would encode it, and the reply the checker would give it.
///
/// Why: lab 6's fresnel_blend() calls mirror_direction(), refracted_direction() and spawn_ray() of labs 4, 5
/// and 2, which a lab 6 worker has only over the link: four round trips a call, 210,000 in lab 6's image
/// test. The checker computes the calls the reference itself makes there (fresnel_blend_answers()) with its
/// own labs, through the very code that answers a real call (serve_op()), and the worker answers a call with
/// exactly these bytes from them, during that served call only; any other call crosses as before. Nothing is
/// handed over that the call would not give: only functions of labs before the graded one, where the graded
/// lab may call them, on numbers the worker was sent, the same calls whatever the hit (both orders of the
/// indices of refraction: which one applies is lab 6's to decide).
struct AnswerAhead {
    std::vector<std::byte> call;  // [op][arguments], as Link::Call encodes them in the worker
    std::vector<std::byte> reply; // the reply's payload
};

/// The lab code of the other side threw: rethrown here as what it was.
struct RemoteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// An exception of the other side that was not a std::exception.
struct RemoteUnknownException {};

/// A tracer made in the worker for an incoming call, standing for the checker's.
struct LocalTracer {
    RayStats stats;
    RenderSettings settings;
    std::unique_ptr<Tracer> tracer;
};

class Link {
  public:
    /// A link over one side of a channel. `remote_labs`: the labs whose code is on the other side.
    Link(Role role, const ChannelFds& fds, LabSet remote_labs);
    Link(const Link&) = delete;
    Link& operator=(const Link&) = delete;

    /// The link of this process, set by the checker's or the worker's main.
    static Link& current();
    static void set_current(Link* link);

    Role role() const { return role_; }
    /// The labs whose code is on the other side.
    LabSet remote_labs() const { return remote_labs_; }
    /// Why the link broke, or empty while it works.
    const std::string& broken() const { return broken_; }
    /// The innermost call to the other side that was in progress when the link broke, as
    /// lab_call_name() says it (the checker only: a worker that dies mid-call died in it); empty if none.
    const std::string& broken_during() const { return broken_during_; }

    /// Serves calls until the other side says goodbye or closes the link (the worker's main loop).
    void serve_until_closed();
    /// Tells the other side that no more calls come.
    void say_goodbye();

    class Call;

    // ---- for the serving side (serve_ops.cpp) ----
    /// The tracer an incoming call of `op` refers to; a worker makes a local
    /// one, kept until the call ends. Throws LinkError for a handle that is not
    /// active, and in the checker for a call its policy does not answer.
    const Tracer& incoming_tracer(Reader& in, Op op);
    /// The scene an incoming scene query refers to.
    const Scene& incoming_scene(Reader& in);
    /// Checks a hit received for `scene` (its indices) before anything uses it.
    void check_hit(const Hit& hit, const Scene& scene);

    /// Worker: the cell of stratified_sample(index, count, .) from the checker, asked once per (index, count)
    /// where the graded lab's code may call stratified_sample(); nothing when the checker's lab 7 is not a grid
    /// of cells. Throws what the checker answers a refused call with.
    std::optional<StratifiedCell> stratified_cell(int index, int count);
    /// Checker: thin_lens_ray(camera, x, y, lens_u) of the worker from a batch asked ahead (LensRaysAhead), asking
    /// for the pixel's next samples when this one starts them; nothing when it must be asked alone.
    std::optional<Ray> thin_lens_ray_ahead(const Camera& camera, double x, double y, Vec2 lens_u);
    /// Checker: the calls of earlier labs that the reference's fresnel_blend(tracer, hit, wo, .) makes, answered
    /// ahead (AnswerAhead); none where those labs are not this program's or not the graded lab's to call.
    std::vector<AnswerAhead> fresnel_blend_answers(const Tracer& tracer, const Hit& hit, const Vec3& wo);

  private:
    friend class Call;
    struct ActiveTracer {
        std::uint64_t handle;
        const Tracer* tracer;
    };

    void send_scene(const Scene& scene);
    std::uint64_t serial_of(const Scene& scene);
    Frame wait_for_reply();
    void serve(const Frame& call);
    void fail(const std::string& reason);
    bool allowed(Op op, const Tracer* tracer) const;
    /// Worker: the answer sent ahead for a call made of exactly these bytes, during the call served now.
    const AnswerAhead* answered_ahead(const std::vector<std::byte>& call, bool with_tracer) const;

    Role role_;
    Channel channel_;
    FrameReader in_;
    LabSet remote_labs_;
    std::recursive_mutex mutex_;
    std::string broken_;
    std::string broken_during_;
    int depth_ = 0;
    std::vector<Op> calls_out_; // the calls this side has made that are still waiting, innermost last
    std::uint64_t next_handle_ = 1;
    std::vector<ActiveTracer> active_; // tracers of the calls in progress, innermost last
    // Checker: serials of scenes the worker holds, oldest first. Worker: the scenes it holds.
    std::vector<std::uint64_t> sent_scenes_;
    std::map<std::uint64_t, std::unique_ptr<Scene>> scenes_;
    std::vector<const Scene*> active_scenes_; // scenes of the calls in progress (checker)
    std::vector<std::unique_ptr<LocalTracer>> local_tracers_; // worker: tracers of the calls it serves
    std::vector<Op> calls_in_;                                  // the calls this side is serving, innermost last
    std::map<std::pair<int, int>, std::optional<StratifiedCell>> cells_; // worker: (index, count) -> cell
    std::map<std::thread::id, LensRaysAhead> lens_rays_;        // checker: a batch per thread of the render
    std::vector<std::vector<AnswerAhead>> answers_ahead_;       // worker: those of each call it serves, innermost last
};

/// One outgoing call: encode the arguments, send, serve what comes back until
/// the reply, decode the result.
class Link::Call {
  public:
    Call(Link& link, Op op);
    ~Call();
    Call(const Call&) = delete;
    Call& operator=(const Call&) = delete;

    Writer& args() { return args_; }
    /// Checker: sends `answers` ahead with this call (AnswerAhead); before any argument.
    void answers_ahead(const std::vector<AnswerAhead>& answers);
    /// Encodes a tracer argument; its state comes back with the reply.
    void tracer(const Tracer& tracer);
    /// Encodes a scene argument (sending the scene first if the other side lacks it).
    void scene(const Scene& scene);
    /// Encodes primitives, for closest_hit().
    void primitives(std::span<const Primitive> primitives);
    /// Sends the call and waits; returns the reply, positioned at the result.
    /// Rethrows what the other side's lab code threw.
    Reader& send();
    /// Checks that the whole reply was read.
    void done();
    /// send(), then the result of type R, then done().
    template <class R>
    R result() {
        R value = send().template get<R>();
        done();
        return value;
    }

  private:
    Link& link_;
    std::unique_lock<std::recursive_mutex> lock_;
    Op op_;
    Writer args_;
    const Tracer* tracer_ = nullptr;
    std::size_t pushed_tracers_ = 0, pushed_scenes_ = 0;
    Frame reply_;
    std::unique_ptr<Reader> reader_;
};

/// Serves one incoming call: decodes the arguments, runs the lab function linked
/// into this program, and encodes [tracer state][result] (serve_ops.cpp).
void serve_op(Link& link, Op op, Reader& in, Writer& out);

} // namespace whitted::link
