// The message of the simcap::Error a piece of code throws, so that a bad-input test can check in
// one expression what the error names (file, line, field, what was expected).
#pragma once

#include <functional>
#include <string>

#include "core/error.h"

namespace simcap::testing {

// The Error's message, or "<no error>" when `f` returns normally.
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace simcap::testing
