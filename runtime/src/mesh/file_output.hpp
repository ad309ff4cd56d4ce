#pragma once
// Files written all or nothing, beside their target. The content goes first to
// a name unique to the process, ".<stem>.<pid>.<what><extension>" in the
// target's folder (two runs writing the same target never share one; the
// extension stays, since writers choose the format by it), and is renamed
// over the target when complete. What a killed run left under such names is
// swept by the next run that writes the same target: its partial and staged
// files removed, a target it had moved aside put back if nothing replaced it.
#include <cstdio>
#include <functional>
#include <string>

namespace stencil_runtime {

// The file an output named `path` lands in: `path` itself or, when it is a
// symbolic link, the file at the end of its chain of links, so that a link
// is kept and what it names is replaced (renaming onto the link would replace
// the link itself). Throws LoadError naming `path` when that file exists and
// is not a regular file: a directory, or a device, FIFO or socket, which
// renaming would delete (`--out /dev/null` used to remove /dev/null).
std::string output_file(const std::string& path);

// ".<stem>.<pid>.<what><extension>" beside `target`.
std::string name_beside(const std::string& target, const char* what);

// Removes the "partial" and "staged" files that dead processes left beside
// `target`, and puts a "previous" one back when `target` is missing (a run
// killed between moving the old file aside and moving the new one in), else
// removes it. Files of live processes are left alone.
void sweep_left_by_killed_runs(const std::string& target);

// Sweeps, writes through `write` to name_beside(output_file(path), "partial")
// and renames it over output_file(path); on any failure removes it and throws
// LoadError naming `path`.
void write_file_atomically(const std::string& path, const std::function<void(std::FILE*)>& write);

}  // namespace stencil_runtime
