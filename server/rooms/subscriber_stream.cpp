#include "subscriber_stream.hpp"

#include <algorithm>

namespace fw::server {
namespace {

constexpr double kFloorBps = 2400;
/// The parameter stream's share of the budget while previews, then full
/// packages, are still on their way; the rest (and whatever the faces leave
/// unused) carries them. A face is not shown before its preview arrives, so
/// previews come first.
constexpr double kParamShareWithPreviews = 0.5;
constexpr double kParamShareWithPackages = 0.7;
constexpr double kParamShare = 0.95;
/// Unspent budget is kept for at most this long, so that no second carries
/// more than 1.1 seconds' worth.
constexpr double kCreditSeconds = 0.1;
constexpr std::size_t kMinChunkBytes = 64;
/// A face that moves is sent this often (frames per second) even while its
/// motion stays within what the prediction shows, so that a viewer sees it
/// alive at 10 frames a second or more on any link whose budget allows it
/// (above 10, because a refresh the budget refuses waits for the next).
constexpr int kRefreshHz = 15;
/// Under this budget per avatar, frames are bundled on the refresh ticks.
constexpr double kBundleBelowBps = 2000;
/// Budget follows need: once a second, a face held under this frame rate by
/// its budget (its rate control's bucket filling) gets a larger share of the
/// stream, one above it a smaller one, within [kMinWeight, kMaxWeight] of an
/// equal share. A busy face then moves as often as a calm one.
constexpr double kFairFps = 12.0;
constexpr double kMinWeight = 0.5, kMaxWeight = 2.5;
/// What the stream aims at, as a share of the client's budget: the rest
/// absorbs what no count here sees (rounding, a late tick, IP headers a
/// client may count).
constexpr double kHeadroom = 0.97;
/// Chat lines waiting for the budget are dropped, oldest first, past this
/// many seconds of it (and past SubscriberStream::kMaxWaitingChat lines).
constexpr double kMaxChatWaitSeconds = 4.0;
/// The room's messages go at once while the budget is overdrawn by less than
/// this (then they wait): a presence or a line as it happens, and a burst
/// of them paid back over the next half second. Only a flood waits.
constexpr double kMessageOverdraftSeconds = 0.5;

}  // namespace

SubscriberStream::SubscriberStream(const StreamSettings& settings, std::shared_ptr<RoomConnection> connection,
                                   Metrics& metrics)
    : settings_(settings), connection_(std::move(connection)), metrics_(metrics),
      effective_bps_(std::max<double>(kFloorBps, settings.budget_bps * kHeadroom)) {
  // The stream header opens the codec stream (after the welcome the room sent).
  send(share(codec::write_stream_header({})));
}

void SubscriberStream::add_avatar(std::uint32_t avatar, SharedBytes preview, SharedBytes full) {
  codec::EncoderOptions options;
  options.stream.tick_rate_hz = static_cast<std::uint8_t>(settings_.tick_hz);
  options.refresh_ticks = std::max(1, settings_.tick_hz / kRefreshHz);
  options.refresh_bucket_share = 1.0;  // a live face at 10+ frames/s first, its finest detail second
  // Frames of one tick share a room frame: its first byte, the message's
  // framing and, when asked for, the timestamp are split among them; each
  // entry adds its id and length.
  const double shared_bytes = 1.0 + 4.0 + (settings_.timestamps ? 13.0 : 0.0);
  options.container_bytes_per_frame = 2.0 + shared_bytes / static_cast<double>(encoders_.size() + 1);
  encoders_.try_emplace(avatar, options);
  if (settings_.packages) {
    // Previews go before every full package, whoever joined first.
    const auto first_full = std::find_if(packages_.begin(), packages_.end(), [](const PackageSend& p) {
      return p.quality == codec::PackageChunk::Quality::full && p.offset == 0;
    });
    if (preview && !preview->empty()) {
      packages_.insert(first_full, {avatar, codec::PackageChunk::Quality::preview, preview, 0});
      awaiting_preview_.insert(avatar);  // its frames would draw nothing yet
    }
    if (full && !full->empty()) packages_.push_back({avatar, codec::PackageChunk::Quality::full, full, 0});
  }
  retarget_encoders();
}

void SubscriberStream::replace_package(std::uint32_t avatar, SharedBytes preview, SharedBytes full) {
  if (!settings_.packages || !encoders_.contains(avatar) || !full || full->empty()) return;
  // What was not started of the old face goes; a package half sent stays
  // (the chunks already out need their end), and the new one follows it.
  std::erase_if(packages_, [avatar](const PackageSend& p) { return p.avatar == avatar && p.offset == 0; });
  const bool preview_on_its_way = std::any_of(packages_.begin(), packages_.end(), [avatar](const PackageSend& p) {
    return p.avatar == avatar && p.quality == codec::PackageChunk::Quality::preview;
  });
  if (awaiting_preview_.contains(avatar) && !preview_on_its_way) {
    // Its frames wait for a preview: the new face's, before every full package.
    const auto first_full = std::find_if(packages_.begin(), packages_.end(), [](const PackageSend& p) {
      return p.quality == codec::PackageChunk::Quality::full && p.offset == 0;
    });
    if (preview && !preview->empty()) packages_.insert(first_full, {avatar, codec::PackageChunk::Quality::preview, preview, 0});
    else awaiting_preview_.erase(avatar);
  }
  packages_.push_back({avatar, codec::PackageChunk::Quality::full, std::move(full), 0});
  retarget_encoders();
}

void SubscriberStream::remove_avatar(std::uint32_t avatar) {
  encoders_.erase(avatar);
  fairness_.erase(avatar);
  awaiting_preview_.erase(avatar);
  // A package half sent stays: the chunks already out need their end to be
  // parsed, and the client drops it with the avatar anyway. Unstarted ones go.
  std::erase_if(packages_, [avatar](const PackageSend& p) { return p.avatar == avatar && p.offset == 0; });
  retarget_encoders();
}

void SubscriberStream::force_key_frames(std::span<const std::uint32_t> avatars) {
  if (avatars.empty()) {
    for (auto& [id, encoder] : encoders_) encoder.force_key_frame();
    return;
  }
  for (const std::uint32_t id : avatars)
    if (auto it = encoders_.find(id); it != encoders_.end()) it->second.force_key_frame();
}

void SubscriberStream::set_budget(std::uint32_t bps) {
  settings_.budget_bps = bps;
  effective_bps_ = std::max<double>(kFloorBps, bps * kHeadroom);
  retarget_encoders();
}

void SubscriberStream::charge(std::size_t bytes) { credit_bytes_ -= static_cast<double>(bytes); }

// --- room messages, within the budget ----------------------------------------

void SubscriberStream::post_presence(codec::Presence::Change change, std::uint32_t avatar, SharedBytes message) {
  if (change == codec::Presence::Change::left) {
    // A face that comes and goes before this client heard of it is never
    // mentioned: under a join/leave flood, a slow link is not filled with
    // the comings and goings of faces it never saw.
    const auto joined = std::find_if(waiting_.begin(), waiting_.end(), [avatar](const Waiting& w) {
      return w.kind == Kind::joined && w.avatar == avatar;
    });
    if (joined != waiting_.end()) {
      waiting_.erase(joined);
      std::erase_if(waiting_, [avatar](const Waiting& w) { return w.kind == Kind::unit_morphs && w.avatar == avatar; });
      return;
    }
  }
  waiting_.push_back({change == codec::Presence::Change::joined ? Kind::joined : Kind::left, avatar, std::move(message)});
  send_messages();
}

void SubscriberStream::post_seats(SharedBytes message) {
  // Each seats message holds everyone's seat: the newest says it all.
  std::erase_if(waiting_, [](const Waiting& w) { return w.kind == Kind::seats; });
  waiting_.push_back({Kind::seats, 0, std::move(message)});
  send_messages();
}

void SubscriberStream::post_attention(const codec::Attention& attention) {
  // Attention is state: entries still waiting are merged, newest wins, and
  // the merged message goes where the newest one would (after every
  // presence that came before it).
  std::erase_if(waiting_, [](const Waiting& w) { return w.kind == Kind::attention; });
  for (const auto& entry : attention.entries) {
    const auto same = std::find_if(waiting_attention_.begin(), waiting_attention_.end(),
                                   [&](const codec::Attention::Entry& e) { return e.avatar == entry.avatar; });
    if (same != waiting_attention_.end()) *same = entry;
    else waiting_attention_.push_back(entry);
  }
  waiting_.push_back({Kind::attention, 0, nullptr});
  send_messages();
}

void SubscriberStream::post_result(SharedBytes message) {
  // A client that sends commands faster than its link carries the answers
  // loses the oldest answers, not its budget.
  post_bounded(Kind::result, kMaxWaitingResults, std::move(message));
}

void SubscriberStream::post_speaking(SharedBytes message) {
  if (settings_.protocol_version < codec::kFirstSpeakingVersion) return;
  // A link too slow for the room's lines loses the oldest announcements:
  // their lines have begun long since.
  post_bounded(Kind::speaking, kMaxWaitingSpeaking, std::move(message));
}

void SubscriberStream::post_unit_morphs(std::uint32_t avatar, SharedBytes message) {
  if (settings_.protocol_version < codec::kFirstUnitMorphsVersion) return;
  // Each holds the avatar's whole set: the newest says it all.
  std::erase_if(waiting_, [avatar](const Waiting& w) { return w.kind == Kind::unit_morphs && w.avatar == avatar; });
  waiting_.push_back({Kind::unit_morphs, avatar, std::move(message)});
  send_messages();
}

void SubscriberStream::post_preview_surface(SharedBytes message) {
  // Version 5 brought it; an older client would refuse a type it does not know.
  if (settings_.protocol_version < codec::kFirstUnitMorphsVersion) return;
  std::erase_if(waiting_, [](const Waiting& w) { return w.kind == Kind::preview_surface; });
  waiting_.push_back({Kind::preview_surface, 0, std::move(message)});
  send_messages();
}

void SubscriberStream::post_bounded(Kind kind, std::size_t max_waiting, SharedBytes message) {
  const auto same = [kind](const Waiting& w) { return w.kind == kind; };
  if (static_cast<std::size_t>(std::count_if(waiting_.begin(), waiting_.end(), same)) >= max_waiting)
    waiting_.erase(std::find_if(waiting_.begin(), waiting_.end(), same));
  waiting_.push_back({kind, 0, std::move(message)});
  send_messages();
}

void SubscriberStream::post_chat(SharedBytes message) {
  chat_bytes_ += message->size();
  chat_.push_back(std::move(message));
  const double max_bytes = effective_bps_ / 8.0 * kMaxChatWaitSeconds;
  while (chat_.size() > kMaxWaitingChat || (chat_.size() > 1 && static_cast<double>(chat_bytes_) > max_bytes))
    drop_oldest_chat();
  send_messages();
}

bool SubscriberStream::congested() const {
  return static_cast<double>(connection_->queued_bytes()) > std::max(512.0, effective_bps_ / 8.0 / 2);
}

bool SubscriberStream::may_send_message() const {
  return credit_bytes_ > -effective_bps_ / 8.0 * kMessageOverdraftSeconds;
}

void SubscriberStream::send_messages() {
  if (!congested() && send_waiting()) send_chat();
}

void SubscriberStream::drop_oldest_chat() {
  chat_bytes_ -= chat_.front()->size();
  chat_.pop_front();
  ++dropped_chat_;
  ++dropped_chat_total_;
}

bool SubscriberStream::send_waiting() {
  while (!waiting_.empty() && may_send_message()) {
    Waiting w = std::move(waiting_.front());
    waiting_.pop_front();
    if (w.kind == Kind::attention) {
      // Entries of faces gone meanwhile mean nothing to the client.
      codec::Attention attention;
      for (const auto& entry : waiting_attention_)
        if (encoders_.count(entry.avatar) && attention.entries.size() < codec::kMaxWelcomeAvatars)
          attention.entries.push_back(entry);
      waiting_attention_.clear();
      if (attention.entries.empty()) continue;
      w.bytes = encode_shared(attention);
    }
    send(std::move(w.bytes));
  }
  return waiting_.empty();
}

void SubscriberStream::send_chat() {
  while (!chat_.empty() && may_send_message()) {
    if (dropped_chat_ > 0) {
      const std::string lines = dropped_chat_ == 1 ? "1 chat line" : std::to_string(dropped_chat_) + " chat lines";
      send(encode_shared(codec::Chat{0, lines + " skipped here: the room chats faster than your link carries"}));
      dropped_chat_ = 0;
    }
    chat_bytes_ -= chat_.front()->size();
    send(std::move(chat_.front()));
    chat_.pop_front();
  }
  // While lines wait, the faces leave them part of the budget.
  if (chat_share_ != !chat_.empty()) {
    chat_share_ = !chat_.empty();
    retarget_encoders();
  }
}

std::uint32_t SubscriberStream::bundle_ticks() const {
  const std::size_t streaming = std::max<std::size_t>(1, encoders_.size() - awaiting_preview_.size());
  const bool thin = effective_bps_ / static_cast<double>(streaming) < kBundleBelowBps;
  return thin ? static_cast<std::uint32_t>(std::max(1, settings_.tick_hz / kRefreshHz)) : 1;
}

void SubscriberStream::retarget_encoders() {
  const std::size_t streaming = encoders_.size() - awaiting_preview_.size();
  if (streaming == 0) return;
  const double share = param_share();
  double weights = 0;
  for (const auto& [id, encoder] : encoders_)
    if (!awaiting_preview_.count(id)) weights += weight_of(id);
  for (auto& [id, encoder] : encoders_) encoder.set_target_bps(effective_bps_ * share * weight_of(id) / weights);
}

double SubscriberStream::param_share() const {
  if (!awaiting_preview_.empty()) return kParamShareWithPreviews;
  return packages_.empty() && !chat_share_ ? kParamShare : kParamShareWithPackages;
}

std::size_t SubscriberStream::send(SharedBytes message) {
  const std::size_t bytes = message->size() + connection_->framing_bytes(message->size());
  credit_bytes_ -= static_cast<double>(bytes);
  connection_->deliver(std::move(message));
  return bytes;
}

void SubscriberStream::tick(std::uint32_t tick, std::uint64_t now_us, std::span<const AvatarFace> faces) {
  if (second_start_us_ == 0) {
    second_start_us_ = now_us;
    written_at_second_start_ = connection_->bytes_written();
  }
  if (now_us - second_start_us_ >= 1'000'000) once_a_second(now_us);

  const double bytes_per_second = effective_bps_ / 8.0;
  credit_bytes_ = std::min(credit_bytes_ + bytes_per_second / settings_.tick_hz,
                           std::max(bytes_per_second * kCreditSeconds, static_cast<double>(kMinChunkBytes) + 16));

  // Latest value wins: a connection still holding half a second of data
  // gets nothing new this tick. The encoders hold (no frame), so the next
  // frame starts from what the client really has.
  const bool congested = this->congested();
  if (congested) {
    ++skipped_ticks_;
    congested_this_second_ = true;
    metrics_.skipped_ticks.fetch_add(1, std::memory_order_relaxed);
  }
  // The room's messages first. While presence, seats, attention or a
  // result waits for the budget, no frame or chunk goes: a face's frames
  // must not overtake the presence that introduces it.
  const bool messages_sent = !congested && send_waiting();
  if (messages_sent) send_chat();
  // On a thin budget the avatars' frames go out together on every
  // bundle_ticks-th tick: one room frame (and one message header) carries
  // them all, instead of one nearly empty room frame per tick.
  const bool send_tick = messages_sent && tick % bundle_ticks() == 0;

  std::vector<codec::RoomEntry>& entries = entries_;  // kept from tick to tick: no allocation per tick
  entries.clear();
  const std::uint32_t bundle = bundle_ticks();
  std::uint64_t reused = 0;
  for (const AvatarFace& face : faces) {
    auto it = encoders_.find(face.id);
    if (it == encoders_.end() || awaiting_preview_.count(face.id)) continue;
    const ViewerEncoding::Offered offered = it->second.offer(tick, face, send_tick, bundle);
    if (!offered.frame.empty()) entries.push_back({face.id, offered.frame});
    reused += offered.reused && !offered.frame.empty();
  }
  if (reused > 0) metrics_.avatar_frames_shared.fetch_add(reused, std::memory_order_relaxed);
  if (!messages_sent) return;
  for (std::size_t start = 0; start < entries.size(); start += codec::kMaxRoomAvatars) {
    const std::size_t count = std::min(codec::kMaxRoomAvatars, entries.size() - start);
    send_room_frames(tick, now_us, std::span(entries).subspan(start, count));
  }
  send_package_chunks();
}

void SubscriberStream::send_room_frames(std::uint32_t tick, std::uint64_t now_us,
                                        std::span<const codec::RoomEntry> entries) {
  std::vector<std::uint8_t> message;
  // Its whole size up front: grown byte by byte it would be copied a few
  // times per message, for every subscriber every tick.
  std::size_t bytes = 32;
  for (const codec::RoomEntry& entry : entries) bytes += entry.frame.size() + 8;
  message.reserve(bytes);
  if (settings_.timestamps) {
    frame_.clear();
    codec::write_room_frame(entries, frame_);
    codec::write_message(codec::TimedRoomFrame{tick, now_us, frame_}, message);
  } else {
    codec::write_room_frame(entries, message);  // the message itself, not a copy of it
  }
  metrics_.room_frames_sent.fetch_add(1, std::memory_order_relaxed);
  metrics_.avatar_frames_sent.fetch_add(entries.size(), std::memory_order_relaxed);
  send(share(std::move(message)));
}

void SubscriberStream::send_package_chunks() {
  // Chunks small enough that a room frame behind one waits at most a
  // quarter of a second on a link that just carries the budget.
  const std::size_t max_chunk = std::clamp<std::size_t>(static_cast<std::size_t>(effective_bps_ / 8 / 4),
                                                        kMinChunkBytes, codec::kMaxChunkBytes);
  while (!packages_.empty() && credit_bytes_ >= static_cast<double>(kMinChunkBytes) + 16) {
    PackageSend& p = packages_.front();
    const std::size_t left = p.bytes->size() - p.offset;
    const std::size_t size =
        std::min({left, max_chunk, static_cast<std::size_t>(credit_bytes_) - 16});
    codec::PackageChunk chunk;
    chunk.avatar = p.avatar;
    chunk.quality = p.quality;
    chunk.total_bytes = static_cast<std::uint32_t>(p.bytes->size());
    chunk.offset = static_cast<std::uint32_t>(p.offset);
    chunk.data.assign(p.bytes->begin() + static_cast<std::ptrdiff_t>(p.offset),
                      p.bytes->begin() + static_cast<std::ptrdiff_t>(p.offset + size));
    p.offset += size;
    metrics_.package_bytes_sent.fetch_add(size, std::memory_order_relaxed);
    send(encode_shared(chunk));
    if (p.offset == p.bytes->size()) {
      const bool preview = p.quality == codec::PackageChunk::Quality::preview;
      if (preview) awaiting_preview_.erase(p.avatar);  // the face can be drawn: stream it
      packages_.pop_front();
      if (preview || packages_.empty()) retarget_encoders();
    }
  }
}

double SubscriberStream::weight_of(std::uint32_t avatar) const {
  const auto it = fairness_.find(avatar);
  return it == fairness_.end() ? 1.0 : it->second.weight;
}

void SubscriberStream::rebalance(double seconds) {
  for (const auto& [id, encoder] : encoders_) {
    if (awaiting_preview_.count(id)) continue;
    Fairness& f = fairness_[id];
    const codec::EncoderStats stats = encoder.stats();
    // The viewer's own count: a shared encoder's counts its group's frames.
    const double fps = static_cast<double>(encoder.frames_sent() - f.frames_at_second_start) / seconds;
    f.frames_at_second_start = encoder.frames_sent();
    const bool held_back = stats.bucket_bits > 0.3 * stats.bucket_capacity_bits;
    if (fps < kFairFps && held_back) f.weight = std::min(kMaxWeight, f.weight * 1.2);
    else if (fps > kFairFps || !held_back) f.weight = std::max(kMinWeight, f.weight / 1.1);
  }
}

void SubscriberStream::once_a_second(std::uint64_t now_us) {
  const std::uint64_t written = connection_->bytes_written();
  const double seconds = static_cast<double>(now_us - second_start_us_) / 1e6;
  const double drain_bps = static_cast<double>(written - written_at_second_start_) * 8.0 / seconds;
  const double requested = std::max<double>(kFloorBps, settings_.budget_bps * kHeadroom);
  rebalance(seconds);
  if (congested_this_second_) {
    // What really left is what the link carries: aim a little under it.
    effective_bps_ = std::clamp(drain_bps * 0.85, kFloorBps, requested);
  } else if (effective_bps_ < requested) {
    effective_bps_ = std::min(requested, effective_bps_ * 1.15 + 800);
  }
  retarget_encoders();
  codec::LinkStats stats;
  stats.target_bps = static_cast<std::uint32_t>(effective_bps_);
  stats.drain_bps = static_cast<std::uint32_t>(drain_bps);
  stats.queued_bytes = static_cast<std::uint32_t>(connection_->queued_bytes());
  stats.skipped_ticks = skipped_ticks_;
  send(encode_shared(stats));
  second_start_us_ = now_us;
  written_at_second_start_ = written;
  congested_this_second_ = false;
}

}  // namespace fw::server
