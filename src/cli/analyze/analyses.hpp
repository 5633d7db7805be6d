// The experiments of `vibra analyze`, one subcommand each (analyze_*.cpp).
#pragma once
#include <CLI/CLI.hpp>

namespace vibra::cli {

void add_convergence_analysis(CLI::App& analyze);
void add_energy_analysis(CLI::App& analyze);
void add_empirical_analysis(CLI::App& analyze);
void add_frequency_analysis(CLI::App& analyze);
void add_fd_accuracy_analysis(CLI::App& analyze);
void add_amplitude_analysis(CLI::App& analyze);
void add_orbit_analysis(CLI::App& analyze);
void add_resonance_analysis(CLI::App& analyze);
void add_period_analysis(CLI::App& analyze);
void add_bounces_analysis(CLI::App& analyze);

}  // namespace vibra::cli
