#include "backend_runner.h"

#include <glad/gl.h>
#include <mygl/context.h>
#include <poll.h>
#include <reference/osmesa_context.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>

namespace fuzz {
namespace {

// Every pixel, 4 bytes each, rows packed (whatever pixel-store state the stream left).
Answer readFrame(GLenum format, GLenum type, AnswerKind kind, const Stream& stream) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(stream.width) * static_cast<std::size_t>(stream.height) *
                                     4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (GLenum pname : {GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_SWAP_BYTES})
        glPixelStorei(pname, 0);
    glReadPixels(0, 0, stream.width, stream.height, format, type, pixels.data());
    return {kind, kFinalFrame, std::move(pixels)};
}

void executeStream(const Stream& stream, Answers& answers) {
    glClearColor(0, 0, 0, 0);
    glClearDepth(1);
    // Stencil and accumulation too: their contents are undefined until cleared (the reference's
    // accumulation buffer holds whatever its memory held, which differs from run to run).
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
    for (std::size_t i = 0; i < stream.calls.size(); ++i) {
        runCall(stream.calls[i], static_cast<std::uint32_t>(i), stream.width, stream.height, answers);
    }
    glEnd();
    glEndList();  // a list left open would compile the reads
    for (int i = 0; i < 8 && glGetError() != GL_NO_ERROR; ++i) {
    }
    glFinish();
    answers.push_back(readFrame(GL_RGBA, GL_UNSIGNED_BYTE, AnswerKind::Color, stream));
    answers.push_back(readFrame(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, AnswerKind::Depth, stream));
}

// The answers on the pipe: for each, kind (1 byte), call index (4), size (4), bytes.
bool writeAll(int fd, const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    while (size > 0) {
        const ssize_t n = write(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

bool sendAnswers(int fd, const Answers& answers) {
    for (const Answer& a : answers) {
        const auto size = static_cast<std::uint32_t>(a.bytes.size());
        if (!writeAll(fd, &a.kind, 1) || !writeAll(fd, &a.call, 4) || !writeAll(fd, &size, 4) ||
            !writeAll(fd, a.bytes.data(), a.bytes.size()))
            return false;
    }
    return true;
}

Answers parseAnswers(const std::vector<std::uint8_t>& data) {
    Answers answers;
    std::size_t at = 0;
    while (at + 9 <= data.size()) {
        Answer a;
        std::uint32_t size;
        a.kind = static_cast<AnswerKind>(data[at]);
        std::memcpy(&a.call, &data[at + 1], 4);
        std::memcpy(&size, &data[at + 5], 4);
        at += 9;
        if (size > data.size() - at) break;  // cut short by a crash
        a.bytes.assign(data.begin() + static_cast<std::ptrdiff_t>(at),
                       data.begin() + static_cast<std::ptrdiff_t>(at + size));
        at += size;
        answers.push_back(std::move(a));
    }
    return answers;
}

[[noreturn]] void childMain(Backend backend, const Stream& stream, int fd) {
    int code = 0;
    try {
        const Answers answers = runStream(backend, stream);
        if (!sendAnswers(fd, answers)) code = 4;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mygl-fuzz child (%s): %s\n", backendName(backend), e.what());
        code = 3;
    }
    close(fd);
    std::exit(code);  // exit, not _exit: LeakSanitizer checks the child at exit
}

struct Child {
    Backend backend = Backend::MyGL;
    pid_t pid = -1;
    int fd = -1;
    std::vector<std::uint8_t> data;
    Outcome outcome;
};

void start(Child& child, const Stream& stream) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::fflush(nullptr);
    child.pid = fork();
    if (child.pid < 0) throw std::runtime_error("fork failed");
    if (child.pid == 0) {
        close(fds[0]);
        childMain(child.backend, stream, fds[1]);
    }
    close(fds[1]);
    child.fd = fds[0];
}

// Reads both children's pipes until both close or the deadline passes.
void collect(std::array<Child, 2>& children, std::chrono::steady_clock::time_point deadline) {
    std::vector<std::uint8_t> buffer(1 << 16);
    for (;;) {
        std::array<pollfd, 2> polls{};
        nfds_t count = 0;
        for (Child& c : children) {
            if (c.fd >= 0) polls[count++] = {c.fd, POLLIN, 0};
        }
        if (count == 0) return;
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) break;
        if (poll(polls.data(), count, static_cast<int>(left.count())) < 0 && errno != EINTR) break;
        for (nfds_t i = 0; i < count; ++i) {
            if (!polls[i].revents) continue;
            for (Child& c : children) {
                if (c.fd != polls[i].fd) continue;
                const ssize_t n = read(c.fd, buffer.data(), buffer.size());
                if (n > 0) {
                    c.data.insert(c.data.end(), buffer.begin(), buffer.begin() + n);
                } else if (n == 0 || errno != EINTR) {
                    close(c.fd);
                    c.fd = -1;
                }
            }
        }
    }
    for (Child& c : children) {  // past the deadline
        if (c.fd < 0) continue;
        kill(c.pid, SIGKILL);
        close(c.fd);
        c.fd = -1;
        c.outcome.status = Outcome::Status::Hung;
    }
}

void reap(Child& child, std::chrono::steady_clock::time_point deadline) {
    int status = 0;
    // A child that closed its pipe may still hang on its way out (destructors, exit handlers).
    while (waitpid(child.pid, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(child.pid, SIGKILL);
            waitpid(child.pid, &status, 0);
            child.outcome.status = Outcome::Status::Hung;
            break;
        }
        usleep(1000);
    }
    child.outcome.answers = parseAnswers(child.data);
    if (child.outcome.status == Outcome::Status::Hung) return;
    if (WIFSIGNALED(status)) {
        child.outcome.status = Outcome::Status::Crashed;
        child.outcome.signal = WTERMSIG(status);
    } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
        child.outcome.status = Outcome::Status::Crashed;
        child.outcome.exitCode = WEXITSTATUS(status);
    }
}

}  // namespace

const char* backendName(Backend backend) { return backend == Backend::MyGL ? "mygl" : "osmesa"; }

std::string Outcome::describe() const {
    switch (status) {
    case Status::Finished: return "finished";
    case Status::Hung: return "hung";
    case Status::Crashed: break;
    }
    if (signal)
        return std::string(sigabbrev_np(signal) ? "SIG" : "signal ") +
               (sigabbrev_np(signal) ? sigabbrev_np(signal) : std::to_string(signal));
    return "exit code " + std::to_string(exitCode);
}

Answers runStream(Backend backend, const Stream& stream) {
    Answers answers;
    if (backend == Backend::MyGL) {
        mygl::Context context(stream.width, stream.height);
        context.makeCurrent();
        executeStream(stream, answers);
    } else {
        reference::OsmesaContext context(stream.width, stream.height);
        context.makeCurrent();
        executeStream(stream, answers);
    }
    return answers;
}

BothOutcomes runOnBothBackends(const Stream& stream, std::chrono::milliseconds timeout) {
    std::array<Child, 2> children;
    children[0].backend = Backend::MyGL;
    children[1].backend = Backend::OSMesa;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (Child& c : children) start(c, stream);
    collect(children, deadline);
    for (Child& c : children) reap(c, deadline);
    return {std::move(children[0].outcome), std::move(children[1].outcome)};
}

}  // namespace fuzz
