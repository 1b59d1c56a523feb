#pragma once

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace plywood::testing {

// Expects options.Validate() to reject `options` with std::invalid_argument whose message starts
// with "<field>:", the contract every options struct's Validate() has (the YAML layer relies on
// it).
template <typename Options>
void ExpectInvalidField(const Options& options, const std::string& field) {
  try {
    options.Validate();
    ADD_FAILURE() << "expected " << field << " to be rejected";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
  }
}

}  // namespace plywood::testing
