#pragma once
// What one viewer server holds at most, so that no client - careless or
// hostile, with or without the token - can make it stop answering the others
// (docs/RELIABILITY.md lists each with the test that holds it).
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace vri::viewer {

// HTTP connections open at once; one more is closed as soon as it is accepted.
inline constexpr int kMaxConnections = 256;
// Pages (WebSocket sessions) open at once; one more is answered 503.
inline constexpr int kMaxSessions = 16;
// Bytes a session may have waiting to be sent before it stops reading the
// client's messages (and so stops making replies) until they leave.
inline constexpr std::size_t kMaxQueuedBytes = std::size_t{64} << 20;
// Memory one page's renders may hold at once (tables, images): a 4096 x 4096
// final frame and its exact reference fit; a table of a gigabyte does not.
inline constexpr std::uint64_t kPageMemory = std::uint64_t{1} << 30;
// After a failed accept (out of file descriptors), the wait before the next.
inline constexpr std::chrono::milliseconds kAcceptRetry{100};

}  // namespace vri::viewer
