// Where a report came from (include/frictionid/io/provenance.hpp).
#include <frictionid/io/provenance.hpp>

#include <string>
#include <utility>
#include <vector>

#include "io/file_fingerprint.hpp"

#ifndef FRICTIONID_VERSION
#error "FRICTIONID_VERSION (project(VERSION)) must be defined for the io library"
#endif

namespace frictionid {

std::string frictionid_version() {
  return FRICTIONID_VERSION;
}

InputFile input_file(const std::string& path) {
  const FileFingerprint f = fingerprint_file(path);
  return InputFile{path, f.size, f.sha256};
}

nlohmann::ordered_json provenance_json(const Provenance& p) {
  nlohmann::ordered_json j;
  j["version"] = p.version;
  j["command_line"] =
      p.command_line.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(p.command_line);
  j["python_call"] =
      p.python_call.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(p.python_call);
  j["options"] = p.options;
  nlohmann::ordered_json inputs = nlohmann::ordered_json::array();
  for (const auto& f : p.inputs)
    inputs.push_back({{"path", f.path}, {"size", f.size}, {"sha256", f.sha256}});
  j["inputs"] = inputs;
  if (!p.data_form.form.empty()) j["data_form"] = data_form_json(p.data_form);
  return j;
}

std::vector<std::pair<std::string, std::string>> provenance_lines(const Provenance& p) {
  std::vector<std::pair<std::string, std::string>> lines;
  lines.emplace_back("frictionid version", p.version);
  if (!p.command_line.empty()) lines.emplace_back("command line", p.command_line);
  if (!p.python_call.empty()) lines.emplace_back("Python call", p.python_call);
  if (p.command_line.empty() && p.python_call.empty())
    lines.emplace_back("command line", "not recorded (the report was written by a library call)");
  if (!p.options.is_null())
    lines.emplace_back(
        "resolved options",
        p.options.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
  for (const auto& f : p.inputs)
    lines.emplace_back(
        "input", f.sha256.empty()
                     ? f.path + " (not fingerprinted: not a regular file, or unreadable)"
                     : f.path + ", " + std::to_string(f.size) + " bytes, SHA-256 " + f.sha256);
  if (p.inputs.empty()) lines.emplace_back("input", "in-memory data (no input file)");
  if (!p.data_form.form.empty()) lines.emplace_back("data form", data_form_text(p.data_form));
  return lines;
}

}  // namespace frictionid
