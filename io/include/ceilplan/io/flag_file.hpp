#pragma once
/// @file
/// A command's flags from a YAML file (`ceilplan COMMAND --config FILE.yaml`): a map of long flag
/// names (`capacity-ah: 5.2`, or `capacity_ah`) to a value, or to a flat list standing for a
/// repeated flag; a map under the chosen command's name holds its flags too.

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

namespace ceilplan::io {

/// One key of a --config file: a long flag and its values.
struct FlagFileEntry {
  std::string flag;                 ///< the long name, '_' spelled '-'
  std::vector<std::string> values;  ///< one per occurrence of the flag
};

/// Refuses (ceilplan::InputError naming the file) a --config file that ceilplan::requireInputFile
/// refuses (missing, a FIFO, device or directory, unreadable) or one larger than 64 MiB; called
/// before the file is opened, since opening a FIFO blocks.
void requireFlagFile(const std::filesystem::path& file);

/// The file's flags in the order written. `known_flags`: the long names the command takes; any
/// other key is refused (a typo would otherwise silently run the default). `command`: the chosen
/// command's name, empty for none. Throws ceilplan::InputError with the line for malformed YAML,
/// a file that is not a map, a key that is not a known flag (with the closest one), or a value
/// that is a map, a nested list or nothing, a flag given twice (also as 'a-b' and 'a_b'), or
/// more than one YAML document.
std::vector<FlagFileEntry> readFlagFile(std::istream& input, const std::vector<std::string>& known_flags,
                                        const std::string& command);

}  // namespace ceilplan::io
