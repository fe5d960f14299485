// --csv's columns. See beyond/kinetic_csv.hpp.
#include "beyond/kinetic_csv.hpp"

#include <fmt/format.h>

#include <iterator>

namespace gas {

// [anchor: csv-columns]
namespace {

// One column of --csv: its name and how its value is read from the figures.
struct Column {
  const char* name;
  double (*value)(const Figures& f, const KineticFigures& k);
};

// Readers for the columns: an average measured (its value or its error), a
// theory with its error, a plain figure of kinetic theory.
template <Average MeasuredFigures::*average>
double measured_value(const Figures&, const KineticFigures& k) {
  return (k.measured.*average).value;
}
template <Average MeasuredFigures::*average>
double measured_error(const Figures&, const KineticFigures& k) {
  return (k.measured.*average).error;
}
template <Average KineticFigures::*theory>
double theory_value(const Figures&, const KineticFigures& k) {
  return (k.*theory).value;
}
template <Average KineticFigures::*theory>
double theory_error(const Figures&, const KineticFigures& k) {
  return (k.*theory).error;
}
// A difference from the theory: only where the theory applies (many balls).
template <Average MeasuredFigures::*average>
double deviation_value(const Figures&, const KineticFigures& k) {
  return k.many_balls ? (k.measured.*average).value : not_known;
}
template <Average MeasuredFigures::*average>
double deviation_error(const Figures&, const KineticFigures& k) {
  return k.many_balls ? (k.measured.*average).error : not_known;
}
template <double KineticFigures::*figure>
double kinetic_value(const Figures&, const KineticFigures& k) {
  return k.*figure;
}

using M = MeasuredFigures;
using K = KineticFigures;

// The columns in order: stage 6's figures, then kinetic theory's (the naming
// convention in data/README.md). A block of columns is appended at
// the end.
constexpr Column columns[] = {
    {"T", [](const Figures& f, const KineticFigures&) { return f.time; }},
    {"T0", [](const Figures& f, const KineticFigures&) { return f.display_step; }},
    {"wall_collisions",
     [](const Figures& f, const KineticFigures&) {
       return static_cast<double>(f.wall_collisions);
     }},
    {"ball_collisions",
     [](const Figures& f, const KineticFigures&) {
       return static_cast<double>(f.ball_collisions);
     }},
    {"mean_speed", [](const Figures& f, const KineticFigures&) { return f.mean_speed; }},
    {"energy", [](const Figures& f, const KineticFigures&) { return f.energy; }},
    {"energy_drift",
     [](const Figures& f, const KineticFigures&) { return f.energy_drift; }},
    {"px", [](const Figures& f, const KineticFigures&) { return f.momentum.x; }},
    {"py", [](const Figures& f, const KineticFigures&) { return f.momentum.y; }},
    {"kT", [](const Figures&, const KineticFigures& k) { return k.theory.kT; }},
    {"averages_since",
     [](const Figures&, const KineticFigures& k) { return k.measured.since; }},
    {"H", [](const Figures&, const KineticFigures& k) { return k.measured.h_now; }},
    {"H_noise", kinetic_value<&K::h_noise>},
    {"H_noise_spread", kinetic_value<&K::h_noise_spread>},
    {"mean_speed_average", measured_value<&M::mean_speed>},
    {"mean_speed_average_error", measured_error<&M::mean_speed>},
    {"mean_speed_average_theory",
     [](const Figures&, const KineticFigures& k) { return k.theory.mean_speed; }},
    {"pressure", measured_value<&M::wall_middle_pressure>},
    {"pressure_error", measured_error<&M::wall_middle_pressure>},
    {"pressure_theory", theory_value<&K::pressure_theory>},
    {"pressure_theory_error", theory_error<&K::pressure_theory>},
    {"pressure_box", measured_value<&M::pressure_box>},
    {"pressure_box_error", measured_error<&M::pressure_box>},
    {"pressure_box_x", measured_value<&M::pressure_box_x>},
    {"pressure_box_x_error", measured_error<&M::pressure_box_x>},
    {"pressure_box_y", measured_value<&M::pressure_box_y>},
    {"pressure_box_y_error", measured_error<&M::pressure_box_y>},
    {"Z", measured_value<&M::bulk_z>},
    {"Z_error", measured_error<&M::bulk_z>},
    {"Z_theory", theory_value<&K::bulk_z_theory>},
    {"Z_theory_error", theory_error<&K::bulk_z_theory>},
    {"Z_deviation", deviation_value<&M::bulk_z_minus_theory>},
    {"Z_deviation_error", deviation_error<&M::bulk_z_minus_theory>},
    {"Z_henderson", kinetic_value<&K::bulk_z_henderson>},
    {"eta_interior", measured_value<&M::interior_area_fraction>},
    {"eta_interior_error", measured_error<&M::interior_area_fraction>},
    {"kT_interior", measured_value<&M::interior_kT>},
    {"kT_interior_error", measured_error<&M::interior_kT>},
    {"Z_box_walls", measured_value<&M::box_z_walls>},
    {"Z_box_walls_error", measured_error<&M::box_z_walls>},
    {"Z_box_virial", measured_value<&M::box_z_virial>},
    {"Z_box_virial_error", measured_error<&M::box_z_virial>},
    {"collision_rate", measured_value<&M::collision_rate>},
    {"collision_rate_error", measured_error<&M::collision_rate>},
    {"collision_rate_theory", theory_value<&K::collision_rate_theory>},
    {"collision_rate_theory_error", theory_error<&K::collision_rate_theory>},
    {"collision_rate_deviation", deviation_value<&M::collision_rate_minus_theory>},
    {"collision_rate_deviation_error", deviation_error<&M::collision_rate_minus_theory>},
    {"collision_rate_box", measured_value<&M::collision_rate_box>},
    {"collision_rate_box_error", measured_error<&M::collision_rate_box>},
    {"mean_free_path", measured_value<&M::mean_free_path>},
    {"mean_free_path_error", measured_error<&M::mean_free_path>},
    {"mean_free_path_theory", theory_value<&K::mean_free_path_theory>},
    {"mean_free_path_theory_error", theory_error<&K::mean_free_path_theory>},
    {"g_contact", measured_value<&M::pair_contact>},
    {"g_contact_error", measured_error<&M::pair_contact>},
    {"g_contact_theory", kinetic_value<&K::pair_contact_theory>},
    {"g_contact_theory_error", kinetic_value<&K::pair_contact_theory_error>},
    {"wall_contact_pressure", measured_value<&M::wall_contact_pressure>},
    {"wall_contact_pressure_error", measured_error<&M::wall_contact_pressure>},
    {"pressure_deviation", deviation_value<&M::pressure_minus_theory>},
    {"pressure_deviation_error", deviation_error<&M::pressure_minus_theory>},
    {"mean_free_path_deviation", deviation_value<&M::mean_free_path_minus_theory>},
    {"mean_free_path_deviation_error", deviation_error<&M::mean_free_path_minus_theory>},
    {"g_contact_deviation", deviation_value<&M::pair_contact_minus_theory>},
    {"g_contact_deviation_error", deviation_error<&M::pair_contact_minus_theory>},
    {"Z_fixed_N_shift", kinetic_value<&K::bulk_z_shift>},
};

}  // namespace

std::string csv_header() {
  std::string header;
  for (const Column& column : columns) {
    if (!header.empty()) header += ',';
    header += column.name;
  }
  return header;
}

std::string csv_row(const Figures& f, const KineticFigures& k) {
  fmt::memory_buffer row;
  for (const Column& column : columns) {
    if (row.size() > 0) row.push_back(',');
    fmt::format_to(std::back_inserter(row), "{:.17g}", column.value(f, k));
  }
  return fmt::to_string(row);
}
// [/anchor: csv-columns]

}  // namespace gas
