#include "support/blackhole_port.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <thread>

namespace puddle::test {

BlackholePort::BlackholePort() {
    listener_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(listener_, reinterpret_cast<sockaddr*>(&a), sizeof a);
    socklen_t len = sizeof a;
    getsockname(listener_, reinterpret_cast<sockaddr*>(&a), &len);
    port_ = ntohs(a.sin_port);
    listen(listener_, 0);  // a queue of one: the fillers below leave no room
    for (int& fd : fillers_) {
        fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
        connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);  // EINPROGRESS for the ones dropped
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the handshakes that fit are done
}

BlackholePort::~BlackholePort() {
    for (int fd : fillers_)
        if (fd >= 0) close(fd);
    if (listener_ >= 0) close(listener_);
}

}  // namespace puddle::test
