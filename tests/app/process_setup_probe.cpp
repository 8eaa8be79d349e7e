// A fresh process that reports what src/app/process_setup.hpp promises, for process_setup_test.cpp (a
// test process has its own threads and arenas already, and must not be changed). With the argument
// `setup` it calls setup_process() first; without, it is the control that shows what glibc does by
// default. It prints one `name value` line per check, SIGPIPE last (without the setup, that write ends it).
#include <malloc.h>
#include <unistd.h>

#include <barrier>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <thread>
#include <vector>

#include "app/process_setup.hpp"

namespace {

// malloc through a volatile pointer: the compiler may otherwise drop a malloc whose block is only freed.
void* volatile last_block = nullptr;
void* allocate(std::size_t bytes) {
    last_block = std::malloc(bytes);
    return last_block;
}

// The arenas glibc has made so far: malloc_info() lists one `<heap nr=` element per arena.
int count_heaps() {
    char* text = nullptr;
    std::size_t size = 0;
    FILE* out = open_memstream(&text, &size);
    malloc_info(0, out);
    std::fclose(out);
    int heaps = 0;
    for (std::string_view rest(text, size); rest.find("<heap nr=") != std::string_view::npos; ++heaps)
        rest.remove_prefix(rest.find("<heap nr=") + 1);
    std::free(text);
    return heaps;
}

// Four threads that each allocate, all alive at once; the arenas counted while they hold their blocks.
int heaps_with_four_allocating_threads() {
    constexpr int threads = 4;
    std::barrier sync(threads + 1);
    std::vector<std::thread> workers;
    for (int i = 0; i < threads; ++i)
        workers.emplace_back([&sync] {
            void* block = allocate(1000);
            sync.arrive_and_wait();  // allocated
            sync.arrive_and_wait();  // counted
            std::free(block);
        });
    sync.arrive_and_wait();
    const int heaps = count_heaps();
    sync.arrive_and_wait();
    for (std::thread& t : workers) t.join();
    return heaps;
}

}  // namespace

int main(int argc, char** argv) {
    std::signal(SIGPIPE, SIG_DFL);  // as a fresh process has it, whatever the test process ignores
    if (argc > 1 && std::string_view(argv[1]) == "setup") puddle::app::setup_process();

    const int heaps_before = count_heaps();
    const int heaps_with_threads = heaps_with_four_allocating_threads();

    // A large block freed: glibc's dynamic mmap threshold would rise to its size (4 MiB), and its trim
    // threshold to twice that.
    std::free(allocate(4 << 20));
    void* mid = allocate(1 << 20);
    const std::size_t mmapped_mid = mallinfo2().hblks;  // 1: the 1 MiB block went to mmap
    std::free(mid);
    // 2 MiB in blocks under either threshold, freed newest first: they merge into the top of the heap,
    // which is given back to the system once it passes the trim threshold.
    std::vector<void*> blocks(64);
    for (void*& b : blocks) b = allocate(32 << 10);
    for (auto b = blocks.rbegin(); b != blocks.rend(); ++b) std::free(*b);
    const std::size_t kept_kib = mallinfo2().keepcost / 1024;

    std::printf(
        "heaps_before %d\nheaps_with_threads %d\nmmapped_after_large_free %zu\nkept_kib_after_free %zu\n",
        heaps_before, heaps_with_threads, mmapped_mid, kept_kib);
    std::fflush(stdout);

    int fds[2];
    if (pipe(fds) != 0) return 2;
    close(fds[0]);
    const bool failed = write(fds[1], "x", 1) < 0;  // without the setup, SIGPIPE ends the process here
    std::printf("closed_pipe_write %s\n", failed && errno == EPIPE ? "EPIPE" : "other");
    return 0;
}
