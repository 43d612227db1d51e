#include "toml_section.hpp"

namespace dpdrng::study {

toml::table parse_toml(const std::string& text, const std::string& origin) {
  try {
    return toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << origin << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    throw InputError(msg.str());
  }
}

}  // namespace dpdrng::study
