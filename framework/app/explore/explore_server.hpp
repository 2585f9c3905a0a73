// `whitted explore`'s web server: one page and what the page asks for, on the loopback interface only,
// answered only to a request that carries the session's token.
//
// Why: the page shows a student's own render and ray trees. On a shared machine (a lab room, a login
// server) every user can connect to every port of 127.0.0.1, so each request must carry a random token
// that only the link printed to the student holds. The server knows nothing of rendering: what it
// serves comes from ExploreContent, so that it can be tested without the labs.
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace whitted {

/// A request the content cannot answer (a pixel outside the picture, a sample that is not there):
/// the page shows its message.
struct ExploreRequestError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// What the server serves. Each function may throw ExploreRequestError (the page shows its message).
struct ExploreContent {
    std::string page;                                                  // GET /: the HTML page
    std::function<nlohmann::json()> state;                             // GET /state: what the page shows beside pictures
    std::function<std::string(const std::string& view)> picture_png;   // GET /picture.png?view=: a picture
    std::function<nlohmann::json(int x, int y, int sample)> tree;      // GET /tree?x=&y=&sample=: one pixel's rays
    std::function<std::string(int x, int y, int sample)> tree_png;     // GET /tree.png?x=&y=&sample=: their picture
};

class ExploreServer {
  public:
    /// A server for `content`; requests must carry `token` (as ?token=...).
    ExploreServer(ExploreContent content, std::string token);
    ~ExploreServer();
    ExploreServer(const ExploreServer&) = delete;
    ExploreServer& operator=(const ExploreServer&) = delete;

    /// Listens on 127.0.0.1:`port` (0: a free port the system picks) in a thread of its own; returns
    /// the port. Throws std::runtime_error when the port cannot be had.
    int start(int port = 0);
    /// Stops listening and waits for the thread; nothing once stopped.
    void stop();
    /// The link to give the student: http://127.0.0.1:PORT/?token=TOKEN.
    std::string url() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// 128 random bits as 32 hexadecimal digits, from the system's source of randomness.
std::string random_token();

} // namespace whitted
