#include <fairsurf/mesh/continuity.h>
#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace fairsurf {

const char* to_string(Continuity c) {
  switch (c) {
    case Continuity::G0: return "G0";
    case Continuity::G1: return "G1";
    case Continuity::G2: return "G2";
  }
  return "G?";
}

std::string delivered_label(Continuity continuity, bool linear) {
  static const char* const geometric[] = {"G0", "G1", "G2"};
  static const char* const linear_labels[] = {"C0 (linear)", "C1 (linear)", "C2 (linear)"};
  const int k = std::clamp(static_cast<int>(continuity), 0, 2);
  return linear ? linear_labels[k] : geometric[k];
}

Continuity parse_continuity(std::string_view text) {
  if (text.size() == 2 && std::toupper(static_cast<unsigned char>(text[0])) == 'G' &&
      text[1] >= '0' && text[1] <= '2')
    return static_cast<Continuity>(text[1] - '0');
  throw InvalidArgument("parse_continuity: '" + std::string(text) +
                        "' is not a continuity (expected G0, G1 or G2)");
}

}  // namespace fairsurf
