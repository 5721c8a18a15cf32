#pragma once
// Teem reports errors through biff; this turns the pending NRRD message into
// one line and clears it.
#include <string>

namespace tg::io {

std::string teemNrrdError();

}  // namespace tg::io
