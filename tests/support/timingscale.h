#pragma once

// How much slower this build runs the code than the release build the timing figures of a
// test were chosen for. A test whose guarantee is about time (a station held off the bus is
// not timed out, a keep-alive keeps a drive alive, a lease runs out) states it at a pace the
// slowest build meets with margin: it multiplies both the time it allows and the time it
// provokes by this factor, so the ratio it proves stays the same.
//
// Under AddressSanitizer + UndefinedBehaviorSanitizer (the asan preset, -O1) the simulator's
// and the link's threads run 2-3x slower, and on CI's two cores with two tests at a time a
// thread is now and then not scheduled for tens of milliseconds: 4 covers both.
namespace dd::test {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr int kTimingScale = 4;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr int kTimingScale = 4;
#else
constexpr int kTimingScale = 1;
#endif
#else
constexpr int kTimingScale = 1;
#endif

} // namespace dd::test
