// The family tables, split by theme; families.cpp puts them in corpus order.
#pragma once

#include "cases/generator/construction.hpp"

namespace tritri::corpus {

void add_contact_families(std::vector<Family>& out);  // 1-7
void add_plane_families(std::vector<Family>& out);    // 8-11
void add_stress_families(std::vector<Family>& out);   // 12-16

}  // namespace tritri::corpus
