// The command line's exit codes (CONTRACT.md section 4), one set for every subcommand.
#pragma once

namespace arealight::cli {

enum Exit { kOk = 0, kBadInput = 1, kUsage = 2, kRuntime = 3 };

}  // namespace arealight::cli
