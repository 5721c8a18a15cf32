#include "io/modules/teem/teem_util.h"

#include <teem/biff.h>
#include <teem/nrrd.h>

#include <cstdlib>

namespace tg::io {

std::string teemNrrdError() {
  char* e = biffGetDone(NRRD);
  std::string s = e ? e : "unknown Teem error";
  std::free(e);
  // biff stacks one line per caller, innermost last: "[nrrd] fn: reason".
  // The innermost reason is the one a user can act on.
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  if (const auto nl = s.find_last_of('\n'); nl != std::string::npos) s = s.substr(nl + 1);
  if (s.rfind("[nrrd] ", 0) == 0) s = s.substr(7);
  if (const auto colon = s.find(": "); colon != std::string::npos && s.find(' ') > colon) s = s.substr(colon + 2);
  return s.empty() ? "unknown Teem error" : s;
}

}  // namespace tg::io
