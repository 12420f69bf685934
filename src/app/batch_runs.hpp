// The runs of `frictionid batch`: its INPUTS (CSV files, globs, directories, manifests) and
// --group-by turned into a list of runs, sorted by label, before anything is fitted, so that a
// bad input stops the batch at once with exit code 2.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/io/summary_table.hpp>
#include "app/requests.hpp"
#include "io/file_fingerprint.hpp"

namespace frictionid::app {

struct BatchRun {
  std::string label;      // summary row label
  std::string directory;  // runs/<directory>: the label with unsafe characters replaced
  std::string path;       // the data file
  FitRequest options;     // the command line's, with the manifest's per-run values applied
  // With --group-by: the loaded file and the rows of this group (in file order); else null and
  // the run reads `path` itself, so that a bad file is a failed run, not a failed batch.
  std::shared_ptr<const Dataset> file_data;
  std::vector<std::size_t> group_rows;
  std::vector<Covariate> covariates;  // manifest columns and group values, as text
  std::uint64_t key = 0;  // hash of the file's bytes, the group and the options (batch journal)
  FileFingerprint input;  // the file's bytes when the batch was planned
};

// Throws InputError (exit 2) for: an input that matches no CSV, a missing file, a manifest
// with no `path` column or a path that does not exist (naming manifest:line:column), a bad
// per-run option value, an unknown --group-by column, two runs with the same label.
// `key_extra` (e.g. the per-run report kind) enters every run's key. What a directory or a glob
// holds that cannot be an input (a FIFO, a device, a loop of symbolic links, an empty directory
// a glob matched) is left out and named in `skipped` ("path: reason"); a file named directly or
// by a manifest that is not a regular file, or a directory that cannot be listed, is an
// InputError.
std::vector<BatchRun> plan_batch_runs(const std::vector<std::string>& inputs, const FitRequest& o,
                                      const std::vector<std::string>& group_columns,
                                      const std::string& key_extra,
                                      std::vector<std::string>* skipped = nullptr);

// Throws InputError (naming `where`) when a covariate (a manifest or --group-by column) would
// take the name of one of the summary table's own columns.
void check_covariate_name(const std::string& name, const std::string& where);

// --trend-x names a covariate every run has or one of the runs' manifest or group-by columns;
// these are known before any fit, so a typo is an InputError (exit 2) listing the covariates.
void check_trend_x(const std::string& name, const std::vector<BatchRun>& runs);

// The rows `rows` of d, every column (extra ones too) in that order.
Dataset select_rows(const Dataset& d, const std::vector<std::size_t>& rows);

}  // namespace frictionid::app
