#pragma once
// Messages with every field set, for tests that need a typical one rather
// than a particular one: the codec's round trips, its golden vectors (which
// the browser's reader decodes too), and the fuzz targets' seeds.
#include "fw/codec/messages.hpp"

namespace fw::test {

/// A hello with every field set, a name outside ASCII among them.
inline codec::Hello sample_hello() {
  codec::Hello hello;
  hello.room = "lobby";
  hello.name = "Zoë";
  hello.avatar = "0123456789abcdef0123456789abcdef";
  hello.token = "fw1.e30.sig";
  hello.max_bps = 9600;
  hello.timestamps = true;
  hello.own_package = true;
  hello.avatar_key = "k3y-_AZaz09k3y-_AZaz09";
  hello.resume = "r-e_sume0123456789abcd";
  return hello;
}

}  // namespace fw::test
