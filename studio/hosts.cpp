// SPDX-License-Identifier: Apache-2.0
#include "studio/hosts.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::app {
namespace {

bool ipv4(const std::string& text, in_addr* out = nullptr) {
  in_addr a{};
  if (inet_pton(AF_INET, text.c_str(), &a) != 1) return false;
  if (out) *out = a;
  return true;
}

bool ipv6(const std::string& text, in6_addr* out = nullptr) {
  in6_addr a{};
  if (inet_pton(AF_INET6, text.c_str(), &a) != 1) return false;
  if (out) *out = a;
  return true;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// "NAME" or "NAME:PORT" or "[V6]" or "[V6]:PORT" → NAME (v6 without brackets) and the port text.
bool split_host(const std::string& text, std::string& name, std::string& port) {
  if (text.empty()) return false;
  if (text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string::npos) return false;
    name = text.substr(1, close - 1);
    const std::string rest = text.substr(close + 1);
    if (rest.empty()) return port.clear(), true;
    if (rest.front() != ':') return false;
    port = rest.substr(1);
    return true;
  }
  const auto colon = text.find(':');
  if (colon != text.rfind(':')) return false;  // an unbracketed v6 address is not a Host
  name = text.substr(0, colon);
  port = colon == std::string::npos ? std::string() : text.substr(colon + 1);
  return true;
}

}  // namespace

StudioHosts::StudioHosts(std::string listen) : listen_(std::move(listen)) {
  in_addr v4{};
  in6_addr v6{};
  if (ipv4(listen_, &v4)) {
    loopback_ = (ntohl(v4.s_addr) >> 24) == 127;
    wildcard_ = v4.s_addr == htonl(INADDR_ANY);
  } else if (ipv6(listen_, &v6)) {
    loopback_ = IN6_IS_ADDR_LOOPBACK(&v6);
    wildcard_ = IN6_IS_ADDR_UNSPECIFIED(&v6);
  } else {
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--listen: must be an IPv4 or IPv6 address of this machine, such as "
                            "0.0.0.0 for all of them (got '{}')",
                            listen_));
  }
  if (!loopback_) {
    std::array<char, 256> name{};
    if (gethostname(name.data(), name.size() - 1) == 0) machine_ = lower(name.data());
  }
}

std::string StudioHosts::url_host() const {
  if (wildcard_) return "127.0.0.1";
  return ipv6(listen_) ? "[" + listen_ + "]" : listen_;
}

bool StudioHosts::allowed_host(const std::string& host, int port) const {
  std::string name, port_text;
  if (!split_host(host, name, port_text)) return false;
  if (!port_text.empty() && port_text != std::to_string(port)) return false;
  name = lower(name);
  if (name == "127.0.0.1" || name == "localhost" || name == "::1") return true;
  if (ipv4(name) || ipv6(name)) {
    // An address: ours by --listen, or any of this machine's when others may connect (a name
    // resolved by an attacker's DNS never arrives as an address).
    if (!loopback_) return wildcard_ || name == lower(listen_);
    in_addr v4{};
    return ipv4(name, &v4) && (ntohl(v4.s_addr) >> 24) == 127 && name == listen_;
  }
  // This machine's own name, as other machines on the network call it (or by mDNS); nothing
  // that merely starts with it, which any domain could.
  return !machine_.empty() && (name == machine_ || name == machine_ + ".local");
}

bool StudioHosts::allowed_origin(const std::string& origin, int port) const {
  constexpr std::string_view scheme = "http://";
  if (origin.rfind(scheme, 0) != 0) return false;
  const std::string host = origin.substr(scheme.size());
  std::string name, port_text;
  // An Origin always carries the port unless it is the scheme's default, which ours never is.
  return split_host(host, name, port_text) && port_text == std::to_string(port) &&
         allowed_host(host, port);
}

}  // namespace ifsfx::app
