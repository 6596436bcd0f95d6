#include "delete_avatar_command.hpp"

#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http.hpp>

#include "command_failure.hpp"
#include "server_url.hpp"

namespace fw::client {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;

struct DeleteArgs {
  std::string server;
  std::string asset;
  std::string key;
};

void run(const DeleteArgs& args) {
  ServerUrl url;
  std::string error;
  if (!parse_server_url(args.server, url, error)) fail_command("delete-avatar", 2, error);
  if (url.scheme != ServerUrl::Scheme::websocket)
    fail_command("delete-avatar", 2,
                 "avatars are deleted on the server's HTTP port, the one of ws://HOST:PORT/ (the TCP port has no HTTP "
                 "API)");
  asio::io_context io;
  beast::tcp_stream stream(io);
  http::response<http::string_body> response;
  try {
    asio::ip::tcp::resolver resolver(io);
    stream.expires_after(std::chrono::seconds(10));
    stream.connect(resolver.resolve(url.host, url.port));
    http::request<http::empty_body> request{http::verb::delete_, "/api/avatars/" + args.asset, 11};
    request.set(http::field::host, url.host + ":" + url.port);
    request.set(http::field::user_agent, "facewire-client");
    request.set("X-Avatar-Key", args.key);
    http::write(stream, request);
    beast::flat_buffer buffer;
    http::read(stream, buffer, response);
  } catch (const boost::system::system_error& e) {
    fail_command("delete-avatar", 1, "no answer from " + url.text + ": " + e.code().message());
  }
  switch (response.result()) {
    case http::status::no_content:
      std::cerr << "facewire-client delete-avatar: avatar " << args.asset << " and its photo are deleted from "
                << url.text << "\n";
      return;
    case http::status::not_found:
      // What the person wanted: nothing of it is left there.
      std::cerr << "facewire-client delete-avatar: " << response.body();
      return;
    default:
      fail_command("delete-avatar", 1,
                   "the server did not delete it (" + std::to_string(response.result_int()) + "): " + response.body());
  }
}

}  // namespace

void add_delete_avatar_command(CLI::App& app) {
  auto args = std::make_shared<DeleteArgs>();
  CLI::App* cmd = app.add_subcommand("delete-avatar", "Delete your uploaded avatar and its photo from a server");
  cmd->add_option("server", args->server, "the server, ws://HOST:PORT/ as for join")->required();
  cmd->add_option("--asset", args->asset, "the avatar's id, as join printed it")->required();
  cmd->add_option("--key", args->key, "the avatar's key, as join printed it")->required();
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::client
