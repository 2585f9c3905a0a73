// A worker that breaks the grading link's protocol on purpose: whatever a
// student's program could do to the bytes and the shared memory. The checker
// must fail every test it runs with it, and say the link broke.
// WHITTED_HOSTILE picks the misbehaviour (see the cases below).
#include "channel.hpp"
#include "lab_link.hpp"
#include "wire.hpp"

#include <cstdlib>
#include <cstring>
#include <string>
#include <sys/mman.h>
#include <unistd.h>

using namespace whitted::link;

int main() {
    const char* mode_env = std::getenv("WHITTED_HOSTILE");
    const std::string mode = mode_env ? mode_env : "";
    Channel channel({3, 4, 5}, false);
    FrameReader in(channel, std::size_t{1} << 28);
    for (;;) {
        Frame frame = in.next(); // wait for the checker's first call (after any scene)
        if (frame.type != FrameType::call) continue;
        if (mode == "garbage") {
            const char bytes[] = "\x07\x00\x00\x00\x09PASSED all tests";
            const std::string junk(bytes, sizeof bytes - 1); // a frame of an unknown type
            channel.write(reinterpret_cast<const std::byte*>(junk.data()), junk.size());
        } else if (mode == "oversized") {
            std::vector<std::byte> big(std::size_t{3} << 20, std::byte{0});
            write_frame(channel, FrameType::reply, big);
        } else if (mode == "short_reply") {
            write_frame(channel, FrameType::reply, {std::byte{1}});
        } else if (mode == "long_reply") {
            write_frame(channel, FrameType::reply, std::vector<std::byte>(4096, std::byte{0}));
        } else if (mode == "goodbye") {
            write_frame(channel, FrameType::bye, {});
        } else if (mode == "scene_from_worker") {
            write_frame(channel, FrameType::scene, {});
        } else if (mode == "wrong_way") {
            // Asks the checker for a pixel's lens rays, a shortcut only the checker asks a worker for.
            Writer call;
            call.raw(static_cast<std::uint16_t>(Op::thin_lens_rays));
            write_frame(channel, FrameType::call, call.bytes());
        } else if (mode == "wrong_way_pixels") {
            // Asks the checker to trace a block of pixels, which only a checker asks of a worker that holds every lab.
            Writer call;
            call.raw(static_cast<std::uint16_t>(Op::tracer_trace_pixels));
            write_frame(channel, FrameType::call, call.bytes());
        } else if (mode == "exit0") {
            _exit(0);
        } else if (mode == "abort") {
            std::abort();
        } else if (mode == "forged_positions") {
            // Publishes a position far beyond what its ring can hold: the first
            // word of the second ring (ring = 3 cache lines of positions, then 1 MiB).
            const std::size_t ring = 192 + (std::size_t{1} << 20);
            void* memory = mmap(nullptr, 2 * ring, PROT_READ | PROT_WRITE, MAP_SHARED, 3, 0);
            if (memory == MAP_FAILED) return 9;
            const std::uint64_t forged = std::uint64_t{1} << 40;
            std::memcpy(static_cast<char*>(memory) + ring, &forged, sizeof forged);
            const std::byte wake{1};
            (void)::write(5, &wake, 1);
        }
        pause(); // keep the link open: the checker must not wait for us
    }
}
