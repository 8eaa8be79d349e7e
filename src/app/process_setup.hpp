#pragma once
// Process-wide settings for a display that runs for months, made once at the start of main (the puddle
// binary and the soak test, which builds the engine the binary builds):
// - A fatal signal (SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT) writes one line and the return addresses to
//   stderr before the default action, so a crash on a wall leaves a trace in the journal.
// - SIGPIPE ignored: a log reader that goes away (`puddle | head`) must not end the display; writes then
//   fail with EPIPE and are dropped (systemd sets the same for services: IgnoreSIGPIPE=yes).
// - One malloc arena (glibc mallopt M_ARENA_MAX, malloc(3)): the worker threads (pipeline compiler,
//   camera, sky decoding) would otherwise each get an arena whose freed memory glibc returns late, and
//   resident memory then wandered by over 1 MiB in the soak test; with one arena it stays flat. Those
//   threads allocate rarely, so sharing the arena costs nothing measurable.
// - Fixed mmap and trim thresholds (M_MMAP_THRESHOLD 256 KiB, M_TRIM_THRESHOLD 512 KiB): glibc's dynamic
//   thresholds rise after a large block (a decoded image) is freed, and freed memory is then kept; the
//   frame loop allocates nothing, so large blocks going straight to mmap costs nothing there.
namespace puddle::app {

void setup_process();

}  // namespace puddle::app
