// The registry of rupture methods: one entry each (solver/method_entry.hpp), in the order the
// job schema lists them. The solver, the job reader and the views ask it what a method is,
// supports and costs instead of naming one; the two built-in entries are listed in
// methods.cpp, and register_method adds one from outside the solver (a test's).
//
//   const MethodEntry& m = method_entry(params.method);
//   if (m.supports.block_height) ...;  std::unique_ptr<RuptureMethod> run = m.make(params);
#pragma once

#include "solver/method_entry.hpp"

#include <string_view>
#include <vector>

namespace slipfront {

// Every method, the built-in ones first (the finite elements, then the spectral BI method),
// then those registered, in the order they were.
const std::vector<const MethodEntry*>& methods();

// The method of a job that names none: the first, the paper's finite elements.
const MethodEntry& default_method();

// The method called `name`, or nullptr.
const MethodEntry* find_method(std::string_view name);

// The entry of `method`; throws std::invalid_argument if no method has its name.
const MethodEntry& method_entry(Method method);

// Adds a method (its entry must outlive the program, and `entry.method`'s name must point
// into storage that does); throws std::invalid_argument if its name is taken. Call it before
// any job is read, from one thread: the registry is read without a lock.
void register_method(const MethodEntry& entry);

} // namespace slipfront
