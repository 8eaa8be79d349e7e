#pragma once
// A TCP port on 127.0.0.1 that never answers a connect: it listens, but its accept queue is full, so
// Linux drops every new SYN and a client's connect() waits (as for a broker host that is down or behind
// a firewall that drops packets; a blocking connect then takes the kernel's SYN timeout, about 130 s).

namespace puddle::test {

class BlackholePort {
public:
    BlackholePort();
    ~BlackholePort();
    BlackholePort(const BlackholePort&) = delete;
    BlackholePort& operator=(const BlackholePort&) = delete;

    int port() const { return port_; }

private:
    int listener_ = -1;
    int fillers_[3] = {-1, -1, -1};  // the connections that fill the queue, never accepted
    int port_ = 0;
};

}  // namespace puddle::test
