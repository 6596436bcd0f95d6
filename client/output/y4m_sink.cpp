#include "y4m_sink.hpp"

namespace fw::client {

std::unique_ptr<Y4mSink> Y4mSink::create(const std::string& path, int width, int height, int fps, std::string& error) {
  auto writer = render::Y4mWriter::create(path, width, height, fps, error);
  if (!writer) {
    error = "--y4m " + error + (width % 2 != 0 || height % 2 != 0 ? "; change --size" : "");
    return nullptr;
  }
  return std::unique_ptr<Y4mSink>(new Y4mSink(std::move(writer)));
}

}  // namespace fw::client
