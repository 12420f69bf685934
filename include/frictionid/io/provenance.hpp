// Where a report came from: the frictionid version, the command line (or Python call) with its
// resolved options, and each input file's size and SHA-256. Every page and report.json print it,
// so that a report found later says what produced it. Nothing in it varies between two runs of
// the same command on the same bytes (no time, no modification time, no host), so reports stay
// byte-identical.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <frictionid/io/data_form.hpp>

namespace frictionid {

// The version of this library, project(VERSION) of CMakeLists.txt (what `frictionid --version`
// prints).
std::string frictionid_version();

struct InputFile {
  std::string path;  // as the user gave it, never made absolute
  std::uint64_t size = 0;
  std::string sha256;  // lower-case hexadecimal; empty: not fingerprinted (e.g. a FIFO)
};

// The file's size and SHA-256 (io/file_fingerprint.hpp; the modification time is left out: it
// changes when the same bytes are copied). Throws InputError when the file cannot be read.
InputFile input_file(const std::string& path);

struct Provenance {
  std::string version = frictionid_version();
  // The command as typed, shell-quoted where needed, non-printable bytes escaped
  // (text::command_line); empty when not run from the command line.
  std::string command_line;
  // The Python call, when made from Python; may be empty there too (then the page says so).
  std::string python_call;
  // The options after defaults and parsing (app::fit_request_json), or null when not known.
  nlohmann::ordered_json options;
  // The files read; empty when the data came from memory (a DataFrame, Python columns).
  std::vector<InputFile> inputs;
  // How the data file (the first input) was read: its form, why, its axes and units; an empty
  // form when not recorded.
  DataForm data_form;
};

// {"version", "command_line", "python_call", "options", "inputs": [{"path", "size", "sha256"}],
// "data_form" (data_form_json, present when recorded)}; an empty command line or call is null.
nlohmann::ordered_json provenance_json(const Provenance& p);

// The lines a page prints, as (label, text) pairs in a fixed order: "frictionid version",
// "command line" (or "Python call"), "resolved options" (one-line JSON), and one "input" per
// file ("data/run.csv, 123456 bytes, SHA-256 ab12…" in full) or "in-memory data", and "data
// form" (data_form_text) when recorded. Plain text;
// the page escapes it.
std::vector<std::pair<std::string, std::string>> provenance_lines(const Provenance& p);

}  // namespace frictionid
