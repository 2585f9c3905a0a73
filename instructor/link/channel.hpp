// The checker and the worker talk through shared memory: two one-way rings,
// one for each direction, with a pipe each to wake a side that sleeps.
//
// Why: a grading test makes hundreds of thousands of calls across the link
// (every pixel of an image test crosses it several times), and on this
// project's machines a pipe round trip costs about 20 µs, which made a lab's
// image test 500 times slower than in one process. A ring in shared memory
// costs no system call while both sides are running: the waiting side spins
// briefly, and only then sleeps on its wake pipe, which also tells it when the
// other side died (end of file).
//
// The worker can write anything into the shared memory at any time. So each
// side keeps its own position privately and only publishes it; the other
// side's position is read once, checked against the ring's size, and the bytes
// are copied out before anyone looks at them. The memory file is sealed
// against shrinking, so it cannot vanish under the checker.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace whitted::link {

/// The descriptors one side of a channel needs: the shared memory and its two wake pipes.
struct ChannelFds {
    int memory = -1;
    int wake_in = -1;  // read end: the other side writes a byte here to wake us
    int wake_out = -1; // write end: to wake the other side
};

/// Both sides' descriptors for a new channel (made by whoever starts the two processes).
struct ChannelPair {
    ChannelFds checker;
    ChannelFds worker;
};

/// Makes the shared memory (sealed) and the wake pipes, all close-on-exec. Throws LinkError.
ChannelPair make_channel_pair();

class Channel {
  public:
    /// One side of the channel; `checker_side` says which ring is whose.
    Channel(const ChannelFds& fds, bool checker_side);
    ~Channel();
    Channel(const Channel&) = delete;
    Channel& operator=(const Channel&) = delete;

    /// Sends all the bytes, waiting while the ring is full. Throws LinkError when the other side is gone.
    void write(const std::byte* data, std::size_t size);
    /// Receives at least one byte (at most `capacity`), waiting until there is one.
    std::size_t read_some(std::byte* data, std::size_t capacity);
    /// Throws LinkError when the positions the other side published are impossible (it wrote over them).
    void check_positions() const;

    struct Ring;

  private:
    void wait_until(std::atomic<std::uint32_t>& sleeping, bool (Channel::*ready)() const);
    void wake(Ring& ring, std::atomic<std::uint32_t> Ring::*sleeping);
    bool can_read() const;
    bool can_write() const;
    std::uint64_t other_position(const std::atomic<std::uint64_t>& position, std::uint64_t mine, bool ahead) const;

    void* memory_ = nullptr;
    Ring* out_ = nullptr; // we produce
    Ring* in_ = nullptr;  // we consume
    int wake_in_ = -1, wake_out_ = -1;
    std::uint64_t written_ = 0; // our position in out_, kept here: the shared copy may be forged
    std::uint64_t read_ = 0;    // our position in in_
    bool one_cpu_ = false; // this process may run on one CPU only: yield instead of spinning
};

} // namespace whitted::link
