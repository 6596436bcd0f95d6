#include "failover_policy.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

using codec::CloseCode;

TEST(FailoverPolicy, AFailedLinkMovesOnAndARefusalNoServerWouldChangeStops) {
  EXPECT_EQ(after_drop(), NextStep::next_server);
  for (const CloseCode code : {CloseCode::normal, CloseCode::rate_limited, CloseCode::handshake_timeout,
                               CloseCode::idle_timeout, CloseCode::shutting_down, CloseCode::server_full,
                               static_cast<CloseCode>(99)})
    EXPECT_EQ(after_closing(code, false), NextStep::next_server) << static_cast<int>(code);
  for (const CloseCode code : {CloseCode::protocol_error, CloseCode::message_too_large, CloseCode::unsupported_version,
                               CloseCode::room_full, CloseCode::unauthorized, CloseCode::bad_request})
    EXPECT_EQ(after_closing(code, false), NextStep::stop) << static_cast<int>(code);
  EXPECT_EQ(after_closing(CloseCode::avatar_being_prepared, false), NextStep::same_server);
}

TEST(FailoverPolicy, AServerThatNeverHadTheFaceGetsItUploadedWhenItRefusesIt) {
  // Unknown avatar (10) and a key of another server key (4) are what such a
  // server says; the other refusals an upload cannot mend.
  EXPECT_EQ(after_closing(CloseCode::bad_request, true), NextStep::upload_here);
  EXPECT_EQ(after_closing(CloseCode::unauthorized, true), NextStep::upload_here);
  EXPECT_EQ(after_closing(CloseCode::room_full, true), NextStep::stop);
  EXPECT_EQ(after_closing(CloseCode::unsupported_version, true), NextStep::stop);
  EXPECT_EQ(after_closing(CloseCode::shutting_down, true), NextStep::next_server);
}

TEST(FailoverPolicy, AnUploadIsTriedElsewhereOnlyWhenThisServerCouldNotTakeIt) {
  for (const int status : {0, 429, 500, 503}) EXPECT_TRUE(another_server_may_take_it(status)) << status;
  for (const int status : {400, 401, 413, 415, 422}) EXPECT_FALSE(another_server_may_take_it(status)) << status;
}

TEST(ServerRotation, GoesRoundTheListFromWhereItStarts) {
  ServerRotation rotation(3, 1);
  EXPECT_EQ(rotation.current(), 1u);
  EXPECT_EQ(rotation.move_on(), 2u);
  EXPECT_EQ(rotation.move_on(), 0u);
  EXPECT_EQ(rotation.move_on(), 1u);
  EXPECT_EQ(rotation.count(), 3u);
  ServerRotation one(1);
  EXPECT_EQ(one.move_on(), 0u);
  ServerRotation none(0, 5);  // no list: one server
  EXPECT_EQ(none.count(), 1u);
  EXPECT_EQ(none.current(), 0u);
}

}  // namespace
}  // namespace fw::client
