// SPDX-License-Identifier: Apache-2.0
// Which Host and Origin headers the studio answers (studio/hosts.h): a DNS-rebinding page reaches
// the server under its own name and is refused; only this server's names and port pass.
#include "studio/hosts.h"

#include <unistd.h>

#include <array>
#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"

namespace ifsfx::app {
namespace {

TEST(studio_hosts, loopback_names_with_our_port_or_none_pass) {
  const StudioHosts hosts;  // 127.0.0.1
  EXPECT_TRUE(hosts.loopback_only());
  EXPECT_TRUE(hosts.allowed_host("127.0.0.1:8080", 8080));
  EXPECT_TRUE(hosts.allowed_host("localhost:8080", 8080));
  EXPECT_TRUE(hosts.allowed_host("LocalHost:8080", 8080));
  EXPECT_TRUE(hosts.allowed_host("[::1]:8080", 8080));
  EXPECT_TRUE(hosts.allowed_host("localhost", 8080));
}

TEST(studio_hosts, another_port_name_or_address_is_refused_on_the_loopback) {
  const StudioHosts hosts;
  EXPECT_FALSE(hosts.allowed_host("127.0.0.1:8081", 8080));
  EXPECT_FALSE(hosts.allowed_host("evil.example:8080", 8080));
  EXPECT_FALSE(hosts.allowed_host("localhost.evil.example:8080", 8080));
  EXPECT_FALSE(hosts.allowed_host("192.0.2.7:8080", 8080));
  EXPECT_FALSE(hosts.allowed_host("127.0.0.2:8080", 8080));  // not the address listened on
  EXPECT_FALSE(hosts.allowed_host("", 8080));
  EXPECT_FALSE(hosts.allowed_host("::1:8080", 8080));  // a v6 address must be bracketed
  EXPECT_FALSE(hosts.allowed_host("[::1:8080", 8080));
}

TEST(studio_hosts, all_addresses_take_any_ip_literal_and_this_machines_name_only) {
  const StudioHosts hosts("0.0.0.0");
  EXPECT_FALSE(hosts.loopback_only());
  EXPECT_EQ(hosts.url_host(), "127.0.0.1");
  EXPECT_TRUE(hosts.allowed_host("192.0.2.7:8080", 8080));
  EXPECT_TRUE(hosts.allowed_host("[2001:db8::1]:8080", 8080));
  EXPECT_FALSE(hosts.allowed_host("192.0.2.7:8081", 8080));
  EXPECT_FALSE(hosts.allowed_host("evil.example:8080", 8080));
  std::array<char, 256> name{};
  ASSERT_EQ(gethostname(name.data(), name.size() - 1), 0);
  const std::string machine = name.data();
  EXPECT_TRUE(hosts.allowed_host(machine + ":8080", 8080));
  EXPECT_TRUE(hosts.allowed_host(machine + ".local:8080", 8080));
  EXPECT_FALSE(hosts.allowed_host(machine + ".evil.example:8080", 8080));
}

TEST(studio_hosts, one_other_address_takes_itself_not_others) {
  const StudioHosts hosts("192.0.2.7");
  EXPECT_FALSE(hosts.loopback_only());
  EXPECT_EQ(hosts.url_host(), "192.0.2.7");
  EXPECT_TRUE(hosts.allowed_host("192.0.2.7:8080", 8080));
  EXPECT_FALSE(hosts.allowed_host("192.0.2.8:8080", 8080));
}

TEST(studio_hosts, a_v6_listen_address_is_bracketed_in_the_url) {
  const StudioHosts hosts("::1");
  EXPECT_TRUE(hosts.loopback_only());
  EXPECT_EQ(hosts.url_host(), "[::1]");
}

TEST(studio_hosts, origin_needs_http_and_our_port) {
  const StudioHosts hosts;
  EXPECT_TRUE(hosts.allowed_origin("http://127.0.0.1:8080", 8080));
  EXPECT_TRUE(hosts.allowed_origin("http://localhost:8080", 8080));
  EXPECT_FALSE(hosts.allowed_origin("http://127.0.0.1", 8080));  // ours is never port 80
  EXPECT_FALSE(hosts.allowed_origin("https://127.0.0.1:8080", 8080));
  EXPECT_FALSE(hosts.allowed_origin("http://127.0.0.1:8081", 8080));
  EXPECT_FALSE(hosts.allowed_origin("http://evil.example:8080", 8080));
  EXPECT_FALSE(hosts.allowed_origin("null", 8080));
}

TEST(studio_hosts, a_host_name_to_listen_on_is_refused) {
  try {
    StudioHosts hosts("example.com");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(),
                 "--listen: must be an IPv4 or IPv6 address of this machine, such as 0.0.0.0 for "
                 "all of them (got 'example.com')");
  }
}

}  // namespace
}  // namespace ifsfx::app
