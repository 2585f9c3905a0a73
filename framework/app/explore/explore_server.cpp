// The web server of `whitted explore` (explore_server.hpp), on cpp-httplib.
#include "explore/explore_server.hpp"

#include <httplib.h>

#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <random>
#include <thread>

namespace whitted {
namespace {

constexpr const char* kHost = "127.0.0.1";

// The value of query parameter `name` as an integer, or an ExploreRequestError saying what is wrong.
int int_parameter(const httplib::Request& request, const char* name) {
    if (!request.has_param(name)) throw ExploreRequestError(std::string("the request has no ") + name);
    const std::string text = request.get_param_value(name);
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw ExploreRequestError(std::string(name) + " must be a whole number, not '" + text.substr(0, 40) + "'");
    return value;
}

void send_json(httplib::Response& response, int status, const nlohmann::json& json) {
    response.status = status;
    response.set_content(json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}

} // namespace

struct ExploreServer::Impl {
    ExploreContent content;
    std::string token;
    httplib::Server server;
    std::thread thread;
    std::atomic<bool> ended{false}; // the thread's listening is over
    int port = 0;
};

ExploreServer::ExploreServer(ExploreContent content, std::string token) : impl_(std::make_unique<Impl>()) {
    impl_->content = std::move(content);
    impl_->token = std::move(token);
    httplib::Server& server = impl_->server;
    Impl& impl = *impl_;
    // The port is this server's alone: not shared with another program that asks for it too (cpp-httplib's
    // default, SO_REUSEPORT, lets a second server of the same user take the same port and half its requests);
    // on Windows, where SO_REUSEADDR would let any program take it over, held exclusively.
    server.set_socket_options([](socket_t socket) {
        int on = 1;
#ifdef _WIN32
        setsockopt(socket, SOL_SOCKET, SO_EXCLUSIVEADDRUSE, reinterpret_cast<const char*>(&on), sizeof on);
#else
        setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on); // a restart may take the port its last run left
#endif
    });
    // Every request, before its route: the token, or 403 and nothing else.
    server.set_pre_routing_handler([&impl](const httplib::Request& request, httplib::Response& response) {
        if (request.has_param("token") && request.get_param_value("token") == impl.token)
            return httplib::Server::HandlerResponse::Unhandled;
        response.status = 403;
        response.set_content("This page needs the link that whitted explore printed (with its token).\n", "text/plain");
        return httplib::Server::HandlerResponse::Handled;
    });
    server.Get("/", [&impl](const httplib::Request&, httplib::Response& response) {
        response.set_content(impl.content.page, "text/html; charset=utf-8");
    });
    server.Get("/state", [&impl](const httplib::Request&, httplib::Response& response) {
        response.set_header("Cache-Control", "no-store");
        send_json(response, 200, impl.content.state());
    });
    server.Get("/picture.png", [&impl](const httplib::Request& request, httplib::Response& response) {
        response.set_header("Cache-Control", "no-store");
        response.set_content(impl.content.picture_png(request.has_param("view") ? request.get_param_value("view") : "picture"),
                             "image/png");
    });
    server.Get("/tree", [&impl](const httplib::Request& request, httplib::Response& response) {
        const int x = int_parameter(request, "x"), y = int_parameter(request, "y");
        const int sample = request.has_param("sample") ? int_parameter(request, "sample") : 0;
        send_json(response, 200, impl.content.tree(x, y, sample));
    });
    server.Get("/tree.png", [&impl](const httplib::Request& request, httplib::Response& response) {
        const int x = int_parameter(request, "x"), y = int_parameter(request, "y");
        const int sample = request.has_param("sample") ? int_parameter(request, "sample") : 0;
        response.set_header("Cache-Control", "no-store");
        response.set_content(impl.content.tree_png(x, y, sample), "image/png");
    });
    // A request the content cannot answer is the page's to show; anything else thrown is a failure of whitted's,
    // told in the terminal too. The server goes on either way.
    server.set_exception_handler([](const httplib::Request& request, httplib::Response& response, std::exception_ptr thrown) {
        try {
            std::rethrow_exception(thrown);
        } catch (const ExploreRequestError& error) { // the page shows it; the terminal too
            std::fprintf(stderr, "whitted explore: %s %s: %s\n", request.method.c_str(), request.path.c_str(), error.what());
            send_json(response, 400, {{"error", error.what()}});
        } catch (const std::exception& error) {
            std::fprintf(stderr, "whitted explore: %s %s: %s\n", request.method.c_str(), request.path.c_str(), error.what());
            send_json(response, 500, {{"error", error.what()}});
        } catch (...) {
            send_json(response, 500, {{"error", "an unknown exception"}});
        }
    });
}

ExploreServer::~ExploreServer() { stop(); }

int ExploreServer::start(int port) {
    httplib::Server& server = impl_->server;
    const int bound = port == 0 ? server.bind_to_any_port(kHost) : (server.bind_to_port(kHost, port) ? port : -1);
    if (bound < 0)
        throw std::runtime_error(port == 0 ? std::string("cannot listen on ") + kHost
                                           : std::string("cannot listen on ") + kHost + ":" + std::to_string(port) +
                                                 " (is another program using it? --port 0 picks a free one)");
    impl_->port = bound;
    std::atomic<bool>& ended = impl_->ended;
    impl_->thread = std::thread([&server, &ended] {
        server.listen_after_bind();
        ended = true;
    });
    // Running before this returns: a stop() that came sooner would find nothing to stop, and the thread would
    // then listen for good.
    while (!server.is_running() && !ended) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (ended) {
        impl_->thread.join();
        throw std::runtime_error(std::string("cannot listen on ") + kHost + ":" + std::to_string(bound));
    }
    return bound;
}

void ExploreServer::stop() {
    if (!impl_ || !impl_->thread.joinable()) return;
    impl_->server.stop();
    impl_->thread.join();
}

std::string ExploreServer::url() const {
    return "http://" + std::string(kHost) + ":" + std::to_string(impl_->port) + "/?token=" + impl_->token;
}

std::string random_token() {
    std::random_device source;
    std::string token;
    char digits[9];
    for (int word = 0; word < 4; ++word) {
        std::snprintf(digits, sizeof digits, "%08x", static_cast<unsigned>(source()));
        token += digits;
    }
    return token;
}

} // namespace whitted
