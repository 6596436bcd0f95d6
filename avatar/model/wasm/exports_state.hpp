#pragma once
// What the browser engine's C functions share: the last error, and handles.
// JavaScript holds packages and avatars by integer handle (it cannot hold a
// C++ object); the objects live here until released.
#include <map>
#include <memory>
#include <string>

namespace fw::wasm {

/// The message of the last call that failed, for fw_last_error().
void set_error(std::string message);

/// Objects of one kind by handle; handles start at 1 so that 0 means "none".
template <typename T>
class Handles {
 public:
  int add(std::unique_ptr<T> object) {
    const int handle = next_++;
    objects_[handle] = std::move(object);
    return handle;
  }
  T* find(int handle) {
    const auto it = objects_.find(handle);
    if (it != objects_.end()) return it->second.get();
    set_error("no such handle: " + std::to_string(handle) + " (released already?)");
    return nullptr;
  }
  void release(int handle) { objects_.erase(handle); }

 private:
  std::map<int, std::unique_ptr<T>> objects_;
  int next_ = 1;
};

}  // namespace fw::wasm
