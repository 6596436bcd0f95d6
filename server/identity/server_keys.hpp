#pragma once
// The server's own secrets: the key that signs avatar keys, kept in the
// data directory so that the keys uploads handed out stay valid across
// restarts, and fresh random keys (resume keys).
#include <filesystem>
#include <string>
#include <string_view>

namespace fw::server {

std::string hmac_sha256(std::string_view secret, std::string_view data);

/// DIR/server.key, made (32 random bytes, readable by the owner only) if
/// it is not there; empty and `error` if it cannot be read or made.
std::string load_or_create_server_key(const std::filesystem::path& dir, std::string& error);

/// A new avatar's id: 128 random bits as 32 lowercase hex digits. Random,
/// not derived from the package or the photo, so that whoever uploads the
/// same bytes again (a package every room member downloads) gets an avatar
/// of their own, and with it a key of their own (PROTOCOL.md 8.1).
std::string new_asset_id();

/// The secret an upload of `asset` answers with (22 base64url characters,
/// 128 bits): whoever holds it may wear the face and delete it (PROTOCOL.md
/// 8.1). Only the upload that made the avatar answers it: since ids are
/// random, nobody else can have it without the server key. (Avatars stored
/// before ids were random have the package's hash as id; their keys, this
/// same function of it, stay valid.)
std::string avatar_key(std::string_view server_key, std::string_view asset);
/// Whether `key` is `asset`'s, compared in constant time.
bool avatar_key_matches(std::string_view server_key, std::string_view asset, std::string_view key);

/// What a cluster keeps of a secret a person holds (a resume key, a join
/// token): its hash, in base64url, enough to recognise the secret when it
/// is shown again, useless to anyone who reads Redis. Empty for empty.
std::string secret_hash(std::string_view secret);
inline std::string resume_hash(std::string_view resume) { return secret_hash(resume); }

/// `bytes` random bytes from the system's generator, in base64url.
std::string random_key(std::size_t bytes = 16);

}  // namespace fw::server
