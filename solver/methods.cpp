#include "solver/methods.hpp"

#include "solver/fe/finite_element_method.hpp"
#include "solver/spectral/spectral_method.hpp"

#include <stdexcept>
#include <string>

namespace slipfront {

namespace {

std::vector<const MethodEntry*>& registry() {
  // A new built-in method: its entry here (defined in its folder).
  static std::vector<const MethodEntry*> all = {&fe::method_entry(), &spectral::method_entry()};
  return all;
}

} // namespace

const std::vector<const MethodEntry*>& methods() {
  return registry();
}

const MethodEntry& default_method() {
  return *registry().front();
}

const MethodEntry* find_method(std::string_view name) {
  for (const MethodEntry* entry : registry())
    if (entry->method.name() == name) return entry;
  return nullptr;
}

const MethodEntry& method_entry(Method method) {
  if (const MethodEntry* entry = find_method(method.name())) return *entry;
  throw std::invalid_argument("no rupture method is called \"" + std::string(method.name()) + "\"");
}

void register_method(const MethodEntry& entry) {
  if (find_method(entry.method.name()) != nullptr)
    throw std::invalid_argument("a rupture method is already called \"" +
                                std::string(entry.method.name()) + "\"");
  registry().push_back(&entry);
}

} // namespace slipfront
