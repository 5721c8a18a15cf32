#pragma once
// The command-line face of render::ShadowParams: --shadows and its parameter
// flags, whose help quotes the struct's defaults.
#include <string>

#include "app/scale/option_table.h"

#include "render/shadow_pass.h"

namespace tg::app {

struct ShadowFlags {
  render::ShadowParams params;
  std::string firstParameterFlag;  // a --shadow-* flag given, for the check below

  void addTo(OptionTable& ap);
  // UsageError for a parameter flag without --shadows (it would do nothing).
  void validate() const;
};

}  // namespace tg::app
