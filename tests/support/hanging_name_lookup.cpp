// LD_PRELOAD shim for tests: a name lookup of any host under `.hang.test` (RFC 6761 reserves .test) does
// not answer for a minute, as a resolver does when its DNS server drops packets; every other lookup is the
// C library's own. Lets a test show that no network call holds up a stop, without a network.
#include <dlfcn.h>
#include <netdb.h>
#include <unistd.h>

#include <cstring>

namespace {

bool hangs(const char* node) {
    if (node == nullptr) return false;
    const std::size_t n = std::strlen(node), suffix = std::strlen(".hang.test");
    return n >= suffix && std::strcmp(node + n - suffix, ".hang.test") == 0;
}

}  // namespace

extern "C" int getaddrinfo(const char* node, const char* service, const struct addrinfo* hints,
                           struct addrinfo** res) {
    if (hangs(node)) {
        for (int i = 0; i < 60; ++i) sleep(1);
        return EAI_AGAIN;
    }
    using Real = int (*)(const char*, const char*, const struct addrinfo*, struct addrinfo**);
    static const auto real = reinterpret_cast<Real>(dlsym(RTLD_NEXT, "getaddrinfo"));
    return real(node, service, hints, res);
}
