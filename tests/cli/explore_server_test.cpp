// `whitted explore`'s server (framework/app/explore/explore_server.hpp) with made-up content, asked as a
// browser asks it: on 127.0.0.1 only, nothing without the session's token, every bad request answered
// with a reason and never the end of the server.
#include "explore/explore_server.hpp"

#include <gtest/gtest.h>
#include <httplib.h>

#include <set>
#include <string>

using namespace whitted;

namespace {

constexpr const char* kToken = "0123456789abcdef0123456789abcdef";

ExploreContent made_up_content() {
    ExploreContent content;
    content.page = "<!doctype html><title>made up</title>";
    content.state = [] { return nlohmann::json{{"width", 4}, {"height", 3}}; };
    content.picture_png = [](const std::string& view) {
        if (view == "nothing") throw ExploreRequestError("no view called 'nothing'");
        return std::string("\x89PNG made up ", 13) + view;
    };
    content.tree = [](int x, int y, int sample) -> nlohmann::json {
        if (x == 99) throw ExploreRequestError("pixel (99, 0) is outside");
        if (x == 98) throw std::logic_error("a failure of whitted's own");
        return {{"x", x}, {"y", y}, {"sample", sample}};
    };
    content.tree_png = [](int x, int y, int sample) {
        return std::string("\x89PNG rays ", 10) + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(sample);
    };
    return content;
}

class ExploreServerTest : public ::testing::Test {
  protected:
    void SetUp() override { port_ = server_.start(0); }
    httplib::Result get(const std::string& path) {
        httplib::Client client("127.0.0.1", port_);
        return client.Get(path);
    }
    ExploreServer server_{made_up_content(), kToken};
    int port_ = 0;
};

} // namespace

TEST_F(ExploreServerTest, TheLinkNamesTheLoopbackAddressThePortAndTheToken) {
    EXPECT_GT(port_, 0);
    EXPECT_EQ(server_.url(), "http://127.0.0.1:" + std::to_string(port_) + "/?token=" + kToken);
}

TEST_F(ExploreServerTest, WithTheTokenEachRouteAnswers) {
    const std::string token = std::string("token=") + kToken;
    auto page = get("/?" + token);
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_EQ(page->body, "<!doctype html><title>made up</title>");
    auto picture = get("/picture.png?" + token);
    ASSERT_TRUE(picture);
    EXPECT_EQ(picture->get_header_value("Content-Type"), "image/png");
    EXPECT_EQ(picture->body, std::string("\x89PNG made up picture", 20)); // the view by default
    auto pass = get("/picture.png?view=normal&" + token);
    ASSERT_TRUE(pass);
    EXPECT_EQ(pass->body, std::string("\x89PNG made up normal", 19));
    auto state = get("/state?" + token);
    ASSERT_TRUE(state);
    EXPECT_EQ(state->get_header_value("Content-Type"), "application/json");
    EXPECT_EQ(nlohmann::json::parse(state->body), (nlohmann::json{{"width", 4}, {"height", 3}}));
    auto rays = get("/tree.png?x=2&y=1&sample=3&" + token);
    ASSERT_TRUE(rays);
    EXPECT_EQ(rays->body, std::string("\x89PNG rays 2 1 3", 15));
    auto tree = get("/tree?x=2&y=1&sample=3&" + token);
    ASSERT_TRUE(tree);
    EXPECT_EQ(tree->status, 200);
    EXPECT_EQ(nlohmann::json::parse(tree->body), (nlohmann::json{{"x", 2}, {"y", 1}, {"sample", 3}}));
}

TEST_F(ExploreServerTest, WithoutTheRightTokenEveryRouteIsRefused) {
    for (const std::string path : {"/", "/picture.png", "/picture.png?view=goal", "/state", "/tree?x=1&y=1", "/tree.png?x=1&y=1", "/nothing"}) {
        for (const std::string& token : {std::string(), std::string("token="), std::string("token=") + std::string(kToken).substr(1),
                                        std::string("token=") + kToken + "0", std::string("TOKEN=") + kToken}) {
            const std::string asked = path + (path.find('?') == std::string::npos ? "?" : "&") + token;
            auto answer = get(asked);
            ASSERT_TRUE(answer) << asked;
            EXPECT_EQ(answer->status, 403) << asked;
            EXPECT_EQ(answer->body.find("made up"), std::string::npos) << asked;
        }
    }
}

TEST_F(ExploreServerTest, ABadRequestGetsItsReasonAndTheServerGoesOn) {
    const std::string token = std::string("&token=") + kToken;
    const struct {
        std::string path;
        int status;
        std::string error;
    } cases[] = {{"/tree?x=99&y=0", 400, "pixel (99, 0) is outside"},
                 {"/tree?x=abc&y=0", 400, "x must be a whole number, not 'abc'"},
                 {"/tree?x=1", 400, "the request has no y"},
                 {"/tree?x=1&y=99999999999999999999", 400, "y must be a whole number, not '99999999999999999999'"},
                 {"/tree.png?x=1&y=-", 400, "y must be a whole number, not '-'"},
                 {"/picture.png?view=nothing", 400, "no view called 'nothing'"},
                 {"/tree?x=98&y=0", 500, "a failure of whitted's own"}};
    for (const auto& c : cases) {
        auto answer = get(c.path + token);
        ASSERT_TRUE(answer) << c.path;
        EXPECT_EQ(answer->status, c.status) << c.path;
        EXPECT_EQ(nlohmann::json::parse(answer->body).value("error", ""), c.error) << c.path;
    }
    auto answer = get("/nowhere?" + token.substr(1));
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->status, 404);
    auto still = get("/tree?x=1&y=2" + token);
    ASSERT_TRUE(still);
    EXPECT_EQ(still->status, 200);
}

#ifdef __linux__
// Linux answers for the whole of 127.0.0.0/8 on its loopback device: a server bound to 127.0.0.1 alone leaves the
// same port free on 127.0.0.2, one bound to every address (0.0.0.0) does not.
TEST(ExploreServer, ListensOnTheLoopbackAddressAlone) {
    ExploreServer server(made_up_content(), kToken);
    const int port = server.start(0);
    httplib::Client other_address("127.0.0.2", port);
    other_address.set_connection_timeout(2);
    EXPECT_FALSE(other_address.Get(std::string("/?token=") + kToken)) << "the page answers on 127.0.0.2";
    httplib::Server elsewhere;
    elsewhere.set_socket_options([](socket_t) {});
    EXPECT_TRUE(elsewhere.bind_to_port("127.0.0.2", port)) << "the server holds more than 127.0.0.1:" << port;
}
#endif

TEST(ExploreServer, APortInUseIsRefusedWithAReason) {
    ExploreServer first(made_up_content(), kToken);
    const int port = first.start(0);
    ExploreServer second(made_up_content(), kToken);
    try {
        second.start(port);
        FAIL() << "a second server on port " << port;
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("cannot listen on 127.0.0.1:" + std::to_string(port)), std::string::npos)
            << error.what();
    }
}

TEST(ExploreServer, TokensAreThirtyTwoHexDigitsAndDiffer) {
    std::set<std::string> seen;
    for (int i = 0; i < 100; ++i) {
        const std::string token = random_token();
        EXPECT_EQ(token.size(), 32u);
        EXPECT_EQ(token.find_first_not_of("0123456789abcdef"), std::string::npos) << token;
        seen.insert(token);
    }
    EXPECT_EQ(seen.size(), 100u);
}
