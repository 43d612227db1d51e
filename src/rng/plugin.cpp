#include "dpdrng/rng/plugin.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/sha256.hpp"

namespace dpdrng::rng {

namespace {

std::string library_path(std::string_view generator_name) {
  const std::string path(generator_name.substr(kPluginPrefix.size()));
  if (path.empty()) throw InputError("generator 'ext:' names no library: use ext:PATH (a shared library, dpdrng/plugin.h)");
  std::error_code ec;
  const auto canonical = std::filesystem::canonical(path, ec);
  if (ec) throw InputError("plug-in '" + path + "': " + ec.message());
  if (!std::filesystem::is_regular_file(canonical))
    throw InputError("plug-in '" + path + "' is not a regular file (a shared library, dpdrng/plugin.h)");
  return canonical.string();
}

void check_api(const std::string& file, const dpdrng_plugin* api) {
  const std::string who = "plug-in '" + file + "'";
  if (api == nullptr) throw InputError(who + ": dpdrng_plugin_get() returned NULL");
  if (api->abi != DPDRNG_PLUGIN_ABI)
    throw InputError(who + " was built for plug-in ABI " + std::to_string(api->abi) + "; this dpdrng reads ABI " +
                     std::to_string(DPDRNG_PLUGIN_ABI) + " (rebuild it against this version's dpdrng/plugin.h)");
  if (api->words != 1 && api->words != 2)
    throw InputError(who + ": words = " + std::to_string(api->words) + " (a block is 1 or 2 64-bit words)");
  if (api->name == nullptr || *api->name == '\0') throw InputError(who + ": its name is NULL or empty");
  if (!api->counter && !api->pair_step && !api->distance)
    throw InputError(who + ": counter, pair_step and distance are all NULL (it supports no seeding)");
}

LoadedPlugin open_plugin(const std::string& file) {
  // RTLD_LOCAL: the plug-in's symbols stay its own. The handle is never closed: a generator outlives every run.
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) throw InputError("plug-in '" + file + "' cannot be loaded: " + dlerror());
  void* get = dlsym(handle, "dpdrng_plugin_get");
  if (get == nullptr) {
    dlclose(handle);
    throw InputError("plug-in '" + file + "' does not export dpdrng_plugin_get (see dpdrng/plugin.h)");
  }
  LoadedPlugin p;
  p.file = file;
  p.sha256 = sha256_file(file);
  p.api = reinterpret_cast<const dpdrng_plugin* (*)()>(get)();
  try {
    check_api(file, p.api);
  } catch (...) {
    dlclose(handle);
    throw;
  }
  p.name = p.api->name;
  std::fprintf(stderr, "dpdrng: loaded plug-in '%s' from %s (sha256 %s)\n", p.name.c_str(), file.c_str(),
               p.sha256.c_str());
  return p;
}

}  // namespace

const LoadedPlugin& load_plugin(std::string_view generator_name) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<LoadedPlugin>> loaded;  // by canonical file
  // By the name as given too: a stream asks for its generator per batch, and resolving the path each time (a
  // system call per component) would cost more than the hash.
  static std::map<std::string, const LoadedPlugin*, std::less<>> named;
  {
    const std::lock_guard lock(mutex);
    if (const auto it = named.find(generator_name); it != named.end()) return *it->second;
  }
  const std::string file = library_path(generator_name);
  const std::lock_guard lock(mutex);
  auto& slot = loaded[file];
  if (!slot) slot = std::make_unique<LoadedPlugin>(open_plugin(file));
  named.emplace(std::string(generator_name), slot.get());
  return *slot;
}

void check_plugin_seeding(const LoadedPlugin& p, Seeding seeding) {
  const bool ok = seeding == Seeding::counter ? p.api->counter != nullptr
                  : seeding == Seeding::distance ? p.api->distance != nullptr
                                                 : p.api->pair_step != nullptr;
  if (!ok)
    throw InputError("plug-in '" + p.name + "' (" + p.file + ") does not support seeding '" +
                     std::string(to_string(seeding)) + "' (its entry is NULL)");
}

}  // namespace dpdrng::rng
