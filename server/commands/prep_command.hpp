#pragma once
#include <CLI/CLI.hpp>

namespace fw::server {

/// Adds `prep PHOTO -o NAME.fwa [--preview SHEET.png] [--face-index N]
/// [--quality Q] [--landmark-model PATH]`: a photo to an avatar package.
void add_prep_command(CLI::App& app);

}  // namespace fw::server
