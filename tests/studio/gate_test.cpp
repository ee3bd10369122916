// SPDX-License-Identifier: Apache-2.0
// The checks before every route (studio/gate.h): the token compared as a secret, taken from the
// header or the cookie, needed on /api/ only; Host and Origin refused with the message the page
// shows.
#include "studio/gate.h"

#include <set>
#include <string>

#include <gtest/gtest.h>

namespace ifsfx::app {
namespace {

constexpr const char* kToken = "0123456789abcdef0123456789abcdef";
constexpr int kPort = 8080;

httplib::Request request(const std::string& path, const std::string& host = "127.0.0.1:8080") {
  httplib::Request req;
  req.path = path;
  if (!host.empty()) req.headers.emplace("Host", host);
  return req;
}

TEST(same_secret, is_equality_of_the_whole_text) {
  EXPECT_TRUE(same_secret(kToken, kToken));
  EXPECT_TRUE(same_secret("", ""));
  EXPECT_FALSE(same_secret(kToken, "0123456789abcdef0123456789abcdeF"));  // the last byte
  EXPECT_FALSE(same_secret(kToken, "1123456789abcdef0123456789abcdef"));  // the first
  EXPECT_FALSE(same_secret(kToken, "0123456789abcdef"));                  // a prefix
  EXPECT_FALSE(same_secret("0123456789abcdef", kToken));
  EXPECT_FALSE(same_secret(kToken, ""));
}

TEST(random_token, is_32_hex_digits_and_new_each_time) {
  std::set<std::string> seen;
  for (int i = 0; i < 8; ++i) {
    const std::string token = random_token();
    ASSERT_EQ(token.size(), 32u);
    EXPECT_EQ(token.find_first_not_of("0123456789abcdef"), std::string::npos) << token;
    seen.insert(token);
  }
  EXPECT_EQ(seen.size(), 8u);
}

TEST(gate, api_requests_need_the_token_in_the_header_or_the_cookie) {
  const Gate gate(StudioHosts(), kToken);
  httplib::Request none = request("/api/presets");
  EXPECT_EQ(gate.refusal(none, kPort),
            "token: every request needs the token of the URL printed at start");
  httplib::Request header = request("/api/presets");
  header.headers.emplace("X-Ifsfx-Token", kToken);
  EXPECT_EQ(gate.refusal(header, kPort), std::nullopt);
  httplib::Request cookie = request("/api/presets");
  // Written out: GCC 12 at -O1 sees a false out-of-bounds copy in `std::string(...) + kToken`.
  cookie.headers.emplace("Cookie", "theme=dark; ifsfx_token=0123456789abcdef0123456789abcdef");
  EXPECT_EQ(gate.refusal(cookie, kPort), std::nullopt);
  httplib::Request wrong = request("/api/presets");
  wrong.headers.emplace("X-Ifsfx-Token", "0123456789abcdef0123456789abcdee");
  wrong.headers.emplace("Cookie", "ifsfx_token=0123456789abcdef");
  EXPECT_NE(gate.refusal(wrong, kPort), std::nullopt);
}

TEST(gate, the_page_itself_needs_no_token) {
  const Gate gate(StudioHosts(), kToken);
  EXPECT_EQ(gate.refusal(request("/"), kPort), std::nullopt);
  EXPECT_EQ(gate.refusal(request("/studio.js"), kPort), std::nullopt);
}

TEST(gate, host_and_origin_are_checked_before_the_token) {
  const Gate gate(StudioHosts(), kToken);
  httplib::Request rebound = request("/api/presets", "evil.example:8080");
  rebound.headers.emplace("X-Ifsfx-Token", kToken);
  EXPECT_EQ(gate.refusal(rebound, kPort),
            "Host: must be 127.0.0.1, localhost or the --listen address (got evil.example:8080)");
  EXPECT_EQ(gate.refusal(request("/", ""), kPort),
            "Host: must be 127.0.0.1, localhost or the --listen address (got )");
  httplib::Request cross = request("/api/presets");
  cross.headers.emplace("Origin", "http://evil.example:8080");
  EXPECT_EQ(gate.refusal(cross, kPort),
            "Origin: must be this server (got http://evil.example:8080)");
  httplib::Request same = request("/api/presets");
  same.headers.emplace("Origin", "http://localhost:8080");
  same.headers.emplace("X-Ifsfx-Token", kToken);
  EXPECT_EQ(gate.refusal(same, kPort), std::nullopt);
}

}  // namespace
}  // namespace ifsfx::app
