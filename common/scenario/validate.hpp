#pragma once
// Semantic checks of a parsed scenario: every value in range, every name resolvable, the parts
// consistent with each other. Each problem names the file, the line and column of the field (or of
// the enclosing message when the field is missing) and the field's path.

#include <string>
#include <vector>

#include <google/protobuf/text_format.h>

#include "scenario/loader.hpp"

namespace entourage::scenario {

void validate(const Scenario& s, const google::protobuf::TextFormat::ParseInfoTree& tree, const std::string& path,
              std::vector<Problem>* problems);

}  // namespace entourage::scenario
