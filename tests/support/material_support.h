// Materials in tests, by their model's table entry (models/model_spec.h): a
// check that walks the model's parameters covers every parameter it has,
// including those a model added later brings.
#pragma once

#include "models/material.h"
#include "models/model_spec.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace m3055::test {

// Success when `a` and `b` wear the same model and every parameter holds
// exactly equal values (==, no tolerance); otherwise names the model or the
// first parameter that differs, with both values.
::testing::AssertionResult same_material(const Material& a, const Material& b);

// One line for failure messages: the model's name, then every parameter,
// e.g. "metal color=(0.9,0.6,0.4) d=0.05 lobes=(0.013,0.2)(0.1,0.4)".
std::string describe(const Material& material);

// The built-in models of `family`, by name in the table's order: tests that
// go through "every classic model" take their list from here, so a model
// added to the table (docs/adding-a-model.md) is covered without touching them.
std::vector<std::string> builtin_models_of(Family family);

}  // namespace m3055::test
