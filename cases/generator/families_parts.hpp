// The families' configs, split by theme over three construction files; families.cpp describes
// the families and gathers their configs.
#pragma once

#include "cases/generator/construction.hpp"

#include <span>

namespace tritri::corpus {

// One config of the family named `family`. Each construction file has a table of them, a row a
// config, in the order of its family's configs; families.cpp gathers them under the families'
// descriptions.
struct FamilyConfig {
  const char* family;
  Config config;
};

std::span<const FamilyConfig> contact_configs();  // families 1-7
std::span<const FamilyConfig> plane_configs();    // 8-11
std::span<const FamilyConfig> stress_configs();   // 12-16

}  // namespace tritri::corpus
