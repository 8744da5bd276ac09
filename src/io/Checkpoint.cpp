// HDF5 checkpoint of a RunState (C API, numbered calls, docs/libraries.md §4).
// Written with HDF5 1.10's file format (checksummed metadata) and every
// non-empty dataset checksummed (Fletcher32), so a damaged file is refused
// rather than read; every index and size is checked against the mesh on read.
// Layout (format 5): datasets /nodes (n×3), /tets (m×4), /boundary_faces (f×3),
// /boundary_tags, /nodal (4n), /bubble (3m), /equivalent_strain (m),
// /elastic_stress (m×6, or empty), /body_ranges (b×6), /remeshes (r×13; r×12
// in format 3, before the material kept; r×10 in format 2, before the load check),
// /dies (d×6), /loads (r×7), /die_fill (r×2, NaN where not measured; absent
// before it was kept), /iterations (i×2), /outputs (k×2) with
// /output_files (strings), /fingerprint (strings: the case, as a resumed run
// compares it), /temperature (n, thermal scenes; empty otherwise) and /heat
// (8: the heat budget and the transfer time done; both absent before they
// were kept), /material_position (n×3, flow lines; empty otherwise, absent
// before them), /folds (r×6: increment, body, centre, area; absent before
// them), /damage (k×m: each damage criterion's D per element; absent before
// damage), /blows (r×12: die, blow, first and last increment, start and end
// time, energy, work, stroke, peak load, last load, over; absent before energy
// presses), /wear (the die wear of every worn die's vertices, one after the
// other) with /wear_sizes (one count per die, 0 without wear) and /body_wear
// with /body_wear_sizes (per body; all absent before die wear),
// /remesh_rebuilt_share (per remesh; absent before it was kept),
// /die_drawing (2: the dies' extent and sampling; absent before chains),
// the linear solver's kept preconditioner in a checkpoint written at a stop
// (solver::KeptSetUp: /kept_entries with /kept_entries_sizes, one list per
// process, /kept_patterns, /kept_nodes (n×3), /kept_pressure_mass (n) and
// /kept_solver (3: the set-up's rate, the iterations beyond it, MUMPS taken
// over); absent when there is none), the remesh check the stop put off in a
// checkpoint written at a remeshing run's stop criterion (scene::RemeshCheck:
// /remesh_check_rate (m), /remesh_check_step (1) and /remesh_check_touching
// (n, int); absent otherwise), scalar
// attributes on the root group.
#include "anvil/io/Checkpoint.h"

#include "anvil/core/error.h"
#include "anvil/core/input_file.h"
#include "anvil/core/processes.h"
#include "anvil/io/atomic_file.h"
#include "anvil/mesh/TetMesh.h"
#include "hdf5_datasets.h"

#include <hdf5.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace anvil::io {

using scene::DieState;
using scene::LoadRecord;
using scene::RemeshRecord;
using scene::RunState;

namespace {

using namespace hdf5;

/// The bytes of an HDF5 file that the core driver builds in memory, taken
/// when HDF5 frees its buffer at H5Fclose, after the last flush. (The copy
/// H5Fget_file_image makes of an open file carries a stale superblock
/// checksum in HDF5 1.10.) The size is that of the last allocation, at least
/// the file's end; HDF5 reads a file longer than its end.
struct ImageCapture {
  std::size_t size = 0;
  std::string image;

  static void* allocate(std::size_t size, H5FD_file_image_op_t, void* self) {
    static_cast<ImageCapture*>(self)->size = size;
    return std::malloc(size);
  }
  static void* copy(void* to, const void* from, std::size_t size, H5FD_file_image_op_t, void*) {
    return std::memcpy(to, from, size);
  }
  static void* resize(void* buffer, std::size_t size, H5FD_file_image_op_t, void* self) {
    static_cast<ImageCapture*>(self)->size = size;
    return std::realloc(buffer, size);
  }
  static herr_t release(void* buffer, H5FD_file_image_op_t op, void* self) {
    auto* capture = static_cast<ImageCapture*>(self);
    if (op == H5FD_FILE_IMAGE_OP_FILE_CLOSE && buffer) capture->image.assign(static_cast<char*>(buffer), capture->size);
    std::free(buffer);
    return 0;
  }
  static void* share(void* self) { return self; }
  static herr_t keep(void*) { return 0; }
};

/// Points as a flat (x, y, z, x, …) array, and back.
std::vector<double> flattened(const std::vector<mesh::Point>& points) {
  std::vector<double> xyz;
  xyz.reserve(3 * points.size());
  for (const mesh::Point& p : points)
    xyz.insert(xyz.end(), p.data(), p.data() + 3);
  return xyz;
}
std::vector<mesh::Point> points(const std::vector<double>& xyz) {
  std::vector<mesh::Point> out;
  out.reserve(xyz.size() / 3);
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    out.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  return out;
}

/// The checkpoint of `s` as the bytes of an HDF5 file. HDF5 builds it in
/// memory (the core driver without a backing store): the disk is written by
/// write_file_atomically alone, so a full disk is one clear error and HDF5
/// is never left with a file it failed to close (it crashes at exit then).
std::string checkpoint_image(const RunState& s, const std::vector<std::string>& fingerprint) {
  ImageCapture capture;
  {
    // HDF5 1.10's format: checksums on the superblock and object headers.
    Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    H5FD_file_image_callbacks_t callbacks{ImageCapture::allocate,
                                          ImageCapture::copy,
                                          ImageCapture::resize,
                                          ImageCapture::release,
                                          ImageCapture::share,
                                          ImageCapture::keep,
                                          &capture};
    if (H5Pset_fapl_core(access, 1 << 16, false) < 0 ||
        H5Pset_libver_bounds(access, H5F_LIBVER_V110, H5F_LIBVER_LATEST) < 0 ||
        H5Pset_file_image_callbacks(access, &callbacks) < 0)
      throw RunError("checkpoint: cannot set up the HDF5 file");
    Handle file(H5Fcreate("checkpoint in memory", H5F_ACC_TRUNC, H5P_DEFAULT, access), H5Fclose);
    if (!file.valid()) throw RunError("checkpoint: cannot create the HDF5 file in memory");
    const int format = 5;
    write_attribute(file, "format", H5T_NATIVE_INT, &format);
    write_attribute(file, "increment", H5T_NATIVE_INT, &s.increment);
    write_attribute(file, "time", H5T_NATIVE_DOUBLE, &s.time);
    write_attribute(file, "newton_iterations", H5T_NATIVE_INT, &s.newton_iterations);
    const double volume[6] = {s.volume.initial,           s.volume.solver,       s.volume.projection,
                              s.volume.largest_increment, s.volume.compensation, s.volume.remeshing};
    write_array(file, "volume", H5T_NATIVE_DOUBLE, volume, 6, 0);
    std::vector<int> ranges;
    for (const mesh::MeshRange& r : s.bodies)
      ranges.insert(ranges.end(), {r.first_node, r.node_count, r.first_tet, r.tet_count, r.first_face, r.face_count});
    write_array(file, "body_ranges", H5T_NATIVE_INT, ranges.data(), s.bodies.size(), 6);
    std::vector<double> remeshes;
    for (const RemeshRecord& r : s.remeshes)
      remeshes.insert(remeshes.end(),
                      {double(r.increment), double(r.body), double(r.nodes_before), double(r.nodes_after),
                       r.worst_quality_before, r.worst_quality_after, r.volume_change, r.strain_integral_change,
                       r.strain_max_change, r.seconds, r.load_old_mesh, r.load_new_mesh, r.material_change});
    write_array(file, "remeshes", H5T_NATIVE_DOUBLE, remeshes.data(), s.remeshes.size(), 13);
    std::vector<double> die_depths, die_overlaps, rebuilt_shares;
    for (const RemeshRecord& r : s.remeshes) {
      die_depths.push_back(r.die_depth_after);
      die_overlaps.push_back(r.die_overlap_after);
      rebuilt_shares.push_back(r.rebuilt_share);
    }
    write_array(file, "remesh_die_depth", H5T_NATIVE_DOUBLE, die_depths.data(), die_depths.size(), 0);
    write_array(file, "remesh_die_overlap", H5T_NATIVE_DOUBLE, die_overlaps.data(), die_overlaps.size(), 0);
    write_array(file, "remesh_rebuilt_share", H5T_NATIVE_DOUBLE, rebuilt_shares.data(), rebuilt_shares.size(), 0);

    const std::vector<double> nodes = flattened(s.mesh.nodes);
    write_array(file, "nodes", H5T_NATIVE_DOUBLE, nodes.data(), s.mesh.nodes.size(), 3);
    std::vector<long long> tets, faces;
    for (const mesh::Tet& t : s.mesh.tets)
      tets.insert(tets.end(), t.begin(), t.end());
    for (const mesh::Triangle& f : s.mesh.boundary_faces)
      faces.insert(faces.end(), f.begin(), f.end());
    write_array(file, "tets", H5T_NATIVE_LLONG, tets.data(), s.mesh.tets.size(), 4);
    write_array(file, "boundary_faces", H5T_NATIVE_LLONG, faces.data(), s.mesh.boundary_faces.size(), 3);
    write_array(file, "boundary_tags", H5T_NATIVE_INT, s.mesh.boundary_tags.data(), s.mesh.boundary_tags.size(), 0);
    write_array(file, "nodal", H5T_NATIVE_DOUBLE, s.unknowns.nodal.data(), s.unknowns.nodal.size(), 0);
    write_array(file, "bubble", H5T_NATIVE_DOUBLE, s.unknowns.bubble.data(), s.unknowns.bubble.size(), 0);
    write_array(file, "equivalent_strain", H5T_NATIVE_DOUBLE, s.equivalent_strain.data(), s.equivalent_strain.size(),
                0);
    write_array(file, "elastic_stress", H5T_NATIVE_DOUBLE, s.elastic_stress.data(), s.elastic_stress.size() / 6, 6);

    std::vector<double> dies;
    for (const DieState& d : s.dies)
      dies.insert(dies.end(),
                  {d.press_time, d.speed_factor, d.stroke, d.displacement.x(), d.displacement.y(), d.displacement.z()});
    write_array(file, "dies", H5T_NATIVE_DOUBLE, dies.data(), s.dies.size(), 6);
    std::vector<double> loads;
    for (const LoadRecord& r : s.loads)
      loads.insert(loads.end(),
                   {double(r.increment), r.time, double(r.surface), r.stroke, r.force.x(), r.force.y(), r.force.z()});
    write_array(file, "loads", H5T_NATIVE_DOUBLE, loads.data(), s.loads.size(), 7);
    std::vector<double> fills;
    for (const LoadRecord& r : s.loads)
      fills.insert(fills.end(), {r.contact_area, r.fill});
    write_array(file, "die_fill", H5T_NATIVE_DOUBLE, fills.data(), s.loads.size(), 2);
    write_array(file, "iterations", H5T_NATIVE_INT, s.iterations.data(), s.iterations.size(), 2);
    write_array(file, "temperature", H5T_NATIVE_DOUBLE, s.temperature.data(), s.temperature.size(), 0);
    write_array(file, "material_position", H5T_NATIVE_DOUBLE, s.material_position.data(),
                s.material_position.size() / 3, 3);
    std::vector<double> folds;
    for (const scene::FoldRecord& f : s.folds)
      folds.insert(folds.end(),
                   {double(f.increment), double(f.body), f.centre.x(), f.centre.y(), f.centre.z(), f.area});
    write_array(file, "folds", H5T_NATIVE_DOUBLE, folds.data(), s.folds.size(), 6);
    std::vector<double> blows;
    for (const scene::BlowRecord& b : s.blows)
      blows.insert(blows.end(),
                   {double(b.die), double(b.blow), double(b.first_increment), double(b.last_increment), b.start_time,
                    b.end_time, b.energy, b.work, b.stroke, b.peak_load, b.load, double(b.over)});
    write_array(file, "blows", H5T_NATIVE_DOUBLE, blows.data(), s.blows.size(), 12);
    write_ragged(file, "wear", s.wear);
    write_ragged(file, "body_wear", s.body_wear);
    std::vector<double> damage;
    for (const std::vector<double>& d : s.damage)
      damage.insert(damage.end(), d.begin(), d.end());
    write_array(file, "damage", H5T_NATIVE_DOUBLE, damage.data(), s.damage.size(), s.mesh.tets.size());
    const scene::HeatBudget& h = s.heat;
    const std::array<double, 8> heat{h.plastic, h.friction,  h.to_dies,      h.to_environment,
                                     h.stored,  h.remeshing, h.initial_heat, s.transfer_time};
    write_array(file, "heat", H5T_NATIVE_DOUBLE, heat.data(), heat.size(), 0);
    const double drawing[2] = {s.die_extent, s.die_sampling};
    write_array(file, "die_drawing", H5T_NATIVE_DOUBLE, drawing, 2, 0);
    std::vector<double> outputs;
    std::string files;
    for (const scene::OutputFrame& e : s.outputs) {
      outputs.insert(outputs.end(), {e.time, double(e.part)});
      files += e.file + '\n';
    }
    write_array(file, "outputs", H5T_NATIVE_DOUBLE, outputs.data(), s.outputs.size(), 2);
    write_array(file, "output_files", H5T_NATIVE_CHAR, files.data(), files.size(), 0);
    if (const solver::KeptSetUp& k = s.kept_setup; !k.empty()) {
      write_ragged(file, "kept_entries", k.entries);
      write_array(file, "kept_patterns", H5T_NATIVE_DOUBLE, k.patterns.data(), k.patterns.size(), 0);
      const std::vector<double> at = flattened(k.nodes);
      write_array(file, "kept_nodes", H5T_NATIVE_DOUBLE, at.data(), k.nodes.size(), 3);
      write_array(file, "kept_pressure_mass", H5T_NATIVE_DOUBLE, k.pressure_mass.data(), k.pressure_mass.size(), 0);
      const double solver[3] = {k.setup_rate, k.extra_iterations, k.direct_fallback ? 1.0 : 0.0};
      write_array(file, "kept_solver", H5T_NATIVE_DOUBLE, solver, 3, 0);
    }
    if (const scene::RemeshCheck& r = s.remesh_check_at_stop; !r.empty()) {
      write_array(file, "remesh_check_rate", H5T_NATIVE_DOUBLE, r.rate.data(), r.rate.size(), 0);
      write_array(file, "remesh_check_step", H5T_NATIVE_DOUBLE, &r.time_step, 1, 0);
      write_array(file, "remesh_check_touching", H5T_NATIVE_INT, r.touching_die.data(), r.touching_die.size(), 0);
    }
    std::string lines;
    for (const std::string& line : fingerprint)
      lines += line + '\n';
    write_array(file, "fingerprint", H5T_NATIVE_CHAR, lines.data(), lines.size(), 0);
  }
  if (capture.image.empty()) throw RunError("checkpoint: HDF5 did not hand over the file it built in memory");
  return std::move(capture.image);
}

} // namespace

void write_checkpoint(const std::string& path, const RunState& s, const std::vector<std::string>& fingerprint) {
  silence();
  io::write_file_atomically(path, checkpoint_image(s, fingerprint));
}

namespace {
/// The state in the open checkpoint `file`; `path` names it in messages.
RunState read_state(hid_t file, const std::string& path) {
  RunState s;
  int format = 0;
  read_attribute(file, path, "format", H5T_NATIVE_INT, &format);
  if (format < 2 || format > 5)
    throw InputError(path + ": checkpoint format " + std::to_string(format) +
                     ", expected 2 to 5 (written by another "
                     "version of anvil: run the case again without --resume)");
  read_attribute(file, path, "increment", H5T_NATIVE_INT, &s.increment);
  read_attribute(file, path, "time", H5T_NATIVE_DOUBLE, &s.time);
  read_attribute(file, path, "newton_iterations", H5T_NATIVE_INT, &s.newton_iterations);
  if (s.increment < 0 || !std::isfinite(s.time) || s.time < 0.0 || s.newton_iterations < 0)
    throw InputError(path + ": checkpoint attributes increment " + std::to_string(s.increment) + ", time " +
                     std::to_string(s.time) + " s, Newton iterations " + std::to_string(s.newton_iterations) +
                     ": expected numbers >= 0 (damaged file)");
  std::vector<double> volume, nodes, nodal, bubble, dies, loads, outputs;
  std::vector<long long> tets, faces;
  std::vector<char> files;
  read_finite_array(file, path, "volume", volume, 6);
  s.volume.initial = volume[0], s.volume.solver = volume[1], s.volume.projection = volume[2];
  s.volume.largest_increment = volume[3], s.volume.compensation = volume[4], s.volume.remeshing = volume[5];
  std::vector<int> ranges;
  read_array(file, path, "body_ranges", H5T_NATIVE_INT, ranges, 6);
  if (ranges.empty()) throw InputError(path + ": checkpoint dataset 'body_ranges' is empty");
  for (std::size_t i = 0; i < ranges.size(); i += 6)
    s.bodies.push_back({ranges[i], ranges[i + 1], ranges[i + 2], ranges[i + 3], ranges[i + 4], ranges[i + 5]});
  std::vector<double> remeshes;
  const std::size_t per_remesh = format == 2 ? 10 : format == 3 ? 12 : 13; // 2: no load check; 3: no material kept
  read_array(file, path, "remeshes", H5T_NATIVE_DOUBLE, remeshes, per_remesh);
  for (std::size_t i = 0; i < remeshes.size(); i += per_remesh) {
    const double* r = &remeshes[i];
    for (int k = 0; k < 4; ++k)
      if (!(r[k] >= 0.0 && r[k] <= std::numeric_limits<int>::max()))
        throw InputError(path + ": checkpoint dataset 'remeshes', record " + std::to_string(i / per_remesh + 1) +
                         ": a count or index out of range (damaged file)");
    s.remeshes.push_back({int(r[0]), int(r[1]), int(r[2]), int(r[3]), r[4], r[5], r[6], r[7], r[8], r[9]});
    if (per_remesh >= 12) s.remeshes.back().load_old_mesh = r[10], s.remeshes.back().load_new_mesh = r[11];
    if (per_remesh >= 13) s.remeshes.back().material_change = r[12];
  }
  // One value per remesh, NaN where unknown; datasets absent before they were kept.
  auto per_remesh_value = [&](const char* name, const char* what, double RemeshRecord::*field) {
    if (H5Lexists(file, name, H5P_DEFAULT) <= 0) return;
    std::vector<double> values;
    read_array(file, path, name, H5T_NATIVE_DOUBLE, values, 1);
    if (values.size() != s.remeshes.size())
      throw InputError(path + ": checkpoint dataset '" + name + "' has " + std::to_string(values.size()) +
                       " records for " + std::to_string(s.remeshes.size()) + " remeshes (damaged file)");
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!std::isnan(values[i]) && !(values[i] >= 0.0 && std::isfinite(values[i])))
        throw InputError(path + ": checkpoint dataset '" + name + "', record " + std::to_string(i + 1) + ": expected " +
                         what + " >= 0 (damaged file)");
      s.remeshes[i].*field = values[i];
    }
  };
  per_remesh_value("remesh_die_depth", "a depth", &RemeshRecord::die_depth_after);
  per_remesh_value("remesh_die_overlap", "a volume", &RemeshRecord::die_overlap_after);
  per_remesh_value("remesh_rebuilt_share", "a share", &RemeshRecord::rebuilt_share);
  read_finite_array(file, path, "nodes", nodes, 3);
  s.mesh.nodes = points(nodes);
  const long long node_count = s.mesh.node_count();
  const auto node_indices = [&](const char* name, const std::vector<long long>& indices, std::size_t per_record) {
    for (std::size_t i = 0; i < indices.size(); ++i)
      if (indices[i] < 0 || indices[i] >= node_count)
        throw InputError(path + ": checkpoint dataset '" + name + "', record " + std::to_string(i / per_record + 1) +
                         ": node " + std::to_string(indices[i]) + " is out of range (the mesh has " +
                         std::to_string(node_count) + " nodes; damaged file)");
  };
  read_array(file, path, "tets", H5T_NATIVE_LLONG, tets, 4);
  node_indices("tets", tets, 4);
  for (std::size_t i = 0; i < tets.size(); i += 4)
    s.mesh.tets.push_back({int(tets[i]), int(tets[i + 1]), int(tets[i + 2]), int(tets[i + 3])});
  read_array(file, path, "boundary_faces", H5T_NATIVE_LLONG, faces, 3);
  node_indices("boundary_faces", faces, 3);
  for (std::size_t i = 0; i < faces.size(); i += 3)
    s.mesh.boundary_faces.push_back({int(faces[i]), int(faces[i + 1]), int(faces[i + 2])});
  mesh::validate(s.mesh, path + ": checkpoint dataset 'tets'");
  read_array(file, path, "boundary_tags", H5T_NATIVE_INT, s.mesh.boundary_tags, 1);
  read_finite_array(file, path, "nodal", nodal, 4);
  read_finite_array(file, path, "bubble", bubble, 3);
  s.unknowns.nodal = Eigen::Map<Eigen::VectorXd>(nodal.data(), static_cast<long>(nodal.size()));
  s.unknowns.bubble = Eigen::Map<Eigen::VectorXd>(bubble.data(), static_cast<long>(bubble.size()));
  read_finite_array(file, path, "equivalent_strain", s.equivalent_strain, 1);
  read_finite_array(file, path, "elastic_stress", s.elastic_stress, 6);
  read_finite_array(file, path, "dies", dies, 6);
  for (std::size_t i = 0; i < dies.size(); i += 6)
    s.dies.push_back({dies[i], dies[i + 1], dies[i + 2], {dies[i + 3], dies[i + 4], dies[i + 5]}});
  read_finite_array(file, path, "loads", loads, 7);
  for (std::size_t i = 0; i < loads.size(); i += 7) {
    if (!(loads[i] >= 0.0 && loads[i] <= s.increment && loads[i + 2] >= 0.0 && loads[i + 2] < 1e6))
      throw InputError(path + ": checkpoint dataset 'loads', record " + std::to_string(i / 7 + 1) + ": increment " +
                       std::to_string(loads[i]) + ", surface " + std::to_string(loads[i + 2]) +
                       " out of range (damaged file)");
    s.loads.push_back(
        {int(loads[i]), loads[i + 1], int(loads[i + 2]), loads[i + 3], {loads[i + 4], loads[i + 5], loads[i + 6]}});
  }
  if (H5Lexists(file, "die_fill", H5P_DEFAULT) > 0) { // absent in checkpoints written before it
    std::vector<double> fills;
    read_array(file, path, "die_fill", H5T_NATIVE_DOUBLE, fills, 2);
    if (fills.size() != 2 * s.loads.size())
      throw InputError(path + ": checkpoint dataset 'die_fill' has " + std::to_string(fills.size() / 2) +
                       " records for " + std::to_string(s.loads.size()) + " loads (damaged file)");
    for (std::size_t i = 0; i < s.loads.size(); ++i) {
      const double area = fills[2 * i], share = fills[2 * i + 1];
      const bool unmeasured = std::isnan(area) && std::isnan(share);
      if (!unmeasured && !(area >= 0.0 && std::isfinite(area) && share >= 0.0 && share <= 1.0))
        throw InputError(path + ": checkpoint dataset 'die_fill', record " + std::to_string(i + 1) +
                         ": expected an area >= 0 and a share in [0, 1] (damaged file)");
      s.loads[i].contact_area = area, s.loads[i].fill = share;
    }
  }
  if (H5Lexists(file, "iterations", H5P_DEFAULT) > 0) { // absent in checkpoints written before it
    std::vector<int> iterations;
    read_array(file, path, "iterations", H5T_NATIVE_INT, iterations, 2);
    for (std::size_t i = 0; i < iterations.size(); i += 2) {
      if (iterations[i] < 0 || iterations[i + 1] < 0)
        throw InputError(path + ": checkpoint dataset 'iterations', record " + std::to_string(i / 2 + 1) +
                         ": a negative count (damaged file)");
      s.iterations.push_back({iterations[i], iterations[i + 1]});
    }
  }
  read_finite_array(file, path, "outputs", outputs, 2);
  read_array(file, path, "output_files", H5T_NATIVE_CHAR, files, 1);
  std::string name;
  std::size_t k = 0;
  for (char ch : files) {
    if (ch != '\n') {
      name += ch;
      continue;
    }
    if (2 * k + 1 >= outputs.size()) throw InputError(path + ": checkpoint output list is inconsistent");
    if (!(outputs[2 * k + 1] >= 0.0 && outputs[2 * k + 1] < 1e6) || name.find('/') != std::string::npos)
      throw InputError(path + ": checkpoint dataset 'outputs', record " + std::to_string(k + 1) +
                       ": part or file name out of range (damaged file)");
    s.outputs.push_back({outputs[2 * k], int(outputs[2 * k + 1]), name});
    name.clear();
    ++k;
  }
  if (H5Lexists(file, "heat", H5P_DEFAULT) > 0) { // absent in checkpoints written before heat
    read_finite_array(file, path, "temperature", s.temperature, 1);
    std::vector<double> heat;
    read_finite_array(file, path, "heat", heat, 1);
    if (heat.size() != 8) throw InputError(path + ": checkpoint dataset 'heat' has a wrong size");
    s.heat = {heat[0], heat[1], heat[2], heat[3], heat[4], heat[5], heat[6]};
    s.transfer_time = heat[7];
  }
  if (H5Lexists(file, "die_drawing", H5P_DEFAULT) > 0) { // absent before chains: drawn from the mesh
    std::vector<double> drawing;
    read_finite_array(file, path, "die_drawing", drawing, 1);
    if (drawing.size() != 2 || drawing[0] < 0.0 || drawing[1] < 0.0)
      throw InputError(path + ": checkpoint dataset 'die_drawing' holds other than 2 sizes >= 0 (damaged file)");
    s.die_extent = drawing[0], s.die_sampling = drawing[1];
  }
  if (H5Lexists(file, "material_position", H5P_DEFAULT) > 0) // absent before flow lines
    read_finite_array(file, path, "material_position", s.material_position, 3);
  if (H5Lexists(file, "folds", H5P_DEFAULT) > 0) { // absent before folds
    std::vector<double> folds;
    read_finite_array(file, path, "folds", folds, 6);
    for (std::size_t i = 0; i < folds.size(); i += 6) {
      if (!(folds[i] >= 0.0 && folds[i] <= s.increment && folds[i + 1] >= 0.0 && folds[i + 1] < 1e6 &&
            folds[i + 5] >= 0.0))
        throw InputError(path + ": checkpoint dataset 'folds', record " + std::to_string(i / 6 + 1) +
                         ": increment, body or area out of range (damaged file)");
      s.folds.push_back({int(folds[i]), int(folds[i + 1]), {folds[i + 2], folds[i + 3], folds[i + 4]}, folds[i + 5]});
    }
  }
  if (H5Lexists(file, "blows", H5P_DEFAULT) > 0) { // absent before energy presses
    std::vector<double> blows;
    read_finite_array(file, path, "blows", blows, 12);
    for (std::size_t i = 0; i < blows.size(); i += 12) {
      const double* b = &blows[i];
      if (!(b[0] >= 0.0 && b[0] < 1e6 && b[1] >= 1.0 && b[1] <= 1e6 && b[2] >= 1.0 && b[2] <= s.increment + 1 &&
            b[3] >= -1.0 && b[3] <= s.increment && b[6] > 0.0 && (b[11] == 0.0 || b[11] == 1.0)))
        throw InputError(path + ": checkpoint dataset 'blows', record " + std::to_string(i / 12 + 1) +
                         ": die, blow, increments, energy or state out of range (damaged file)");
      s.blows.push_back({.die = int(b[0]),
                         .blow = int(b[1]),
                         .first_increment = int(b[2]),
                         .last_increment = int(b[3]),
                         .start_time = b[4],
                         .end_time = b[5],
                         .energy = b[6],
                         .work = b[7],
                         .stroke = b[8],
                         .peak_load = b[9],
                         .load = b[10],
                         .over = b[11] == 1.0});
    }
  }
  s.wear = read_ragged(file, path, "wear"); // absent before die wear: empty
  s.body_wear = read_ragged(file, path, "body_wear");
  if (H5Lexists(file, "damage", H5P_DEFAULT) > 0) { // absent before damage
    std::vector<double> damage;
    read_finite_array(file, path, "damage", damage, s.mesh.tets.size());
    for (auto d = damage.begin(); d != damage.end(); d += static_cast<long>(s.mesh.tets.size()))
      s.damage.emplace_back(d, d + static_cast<long>(s.mesh.tets.size()));
  }
  if (H5Lexists(file, "kept_solver", H5P_DEFAULT) > 0) { // written at a stop with a kept preconditioner
    solver::KeptSetUp& kept = s.kept_setup;
    std::vector<double> solver, at;
    read_finite_array(file, path, "kept_solver", solver, 1);
    read_finite_array(file, path, "kept_patterns", kept.patterns, 1);
    read_finite_array(file, path, "kept_nodes", at, 3);
    read_finite_array(file, path, "kept_pressure_mass", kept.pressure_mass, 1);
    kept.entries = read_ragged(file, path, "kept_entries");
    const std::size_t kept_nodes = kept.entries.empty() ? 0 : s.mesh.nodes.size();
    if (solver.size() != 3 || kept.patterns.size() != kept.entries.size() || at.size() != 3 * kept_nodes ||
        kept.pressure_mass.size() != kept_nodes)
      throw InputError(path + ": checkpoint datasets of the kept preconditioner do not match the mesh (damaged file)");
    kept.nodes = points(at);
    kept.setup_rate = solver[0], kept.extra_iterations = solver[1], kept.direct_fallback = solver[2] != 0.0;
  }
  if (H5Lexists(file, "remesh_check_step", H5P_DEFAULT) > 0) { // written at a remeshing run's stop
    scene::RemeshCheck& check = s.remesh_check_at_stop;
    std::vector<double> step;
    read_finite_array(file, path, "remesh_check_step", step, 1);
    read_finite_array(file, path, "remesh_check_rate", check.rate, 1);
    read_array(file, path, "remesh_check_touching", H5T_NATIVE_INT, check.touching_die, 1);
    const bool dies_known = std::all_of(check.touching_die.begin(), check.touching_die.end(),
                                        [&](int die) { return die >= -1 && die < static_cast<int>(s.dies.size()); });
    if (step.size() != 1 || !(step[0] > 0.0) || check.rate.size() != s.mesh.tets.size() ||
        check.touching_die.size() != s.mesh.nodes.size() || !dies_known)
      throw InputError(path +
                       ": checkpoint datasets of the remesh check at the stop do not match the mesh (damaged file)");
    check.time_step = step[0];
  }
  if (3 * s.mesh.tet_count() != s.unknowns.bubble.size() || 4 * s.mesh.node_count() != s.unknowns.nodal.size() ||
      (!s.temperature.empty() && s.temperature.size() != s.mesh.nodes.size()) ||
      (!s.material_position.empty() && s.material_position.size() != 3 * s.mesh.nodes.size()) ||
      s.equivalent_strain.size() != s.mesh.tets.size() ||
      (!s.elastic_stress.empty() && s.elastic_stress.size() != 6 * s.mesh.tets.size()) ||
      s.mesh.boundary_tags.size() != s.mesh.boundary_faces.size())
    throw InputError(path + ": checkpoint arrays do not match the mesh");
  // The bodies follow one another and make up the whole mesh.
  mesh::MeshRange end;
  for (const mesh::MeshRange& r : s.bodies) {
    if (r.first_node != end.first_node || r.first_tet != end.first_tet || r.first_face != end.first_face ||
        r.node_count < 0 || r.tet_count < 0 || r.face_count < 0)
      throw InputError(path + ": checkpoint body ranges do not follow one another");
    end = {r.first_node + r.node_count, 0, r.first_tet + r.tet_count, 0, r.first_face + r.face_count, 0};
  }
  if (end.first_node != s.mesh.node_count() || end.first_tet != s.mesh.tet_count() ||
      end.first_face != static_cast<int>(s.mesh.boundary_faces.size()))
    throw InputError(path + ": checkpoint body ranges do not cover the mesh");
  return s;
}
} // namespace

namespace {
/// Throws InputError unless `path` is a checkpoint file that may be opened.
void require_checkpoint_file(const std::string& path) {
  const std::string problem = input_file_problem(path, kMaxCheckpointBytes);
  if (problem == "file not found") throw InputError(path + ": no checkpoint to resume from");
  if (!problem.empty()) throw InputError(path + ": " + problem);
}
} // namespace

RunState read_checkpoint(const std::string& path) {
  silence();
  require_checkpoint_file(path);
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw InputError(path + ": not a readable HDF5 checkpoint (damaged, or not a checkpoint)");
  return read_state(file, path);
}

void share_state(RunState& state) {
  if (processes::count() == 1) return;
  silence();
  std::string image = processes::root() ? checkpoint_image(state, {}) : std::string();
  processes::broadcast(image);
  std::vector<double> inside_dies = state.inside_dies; // measured, not in a checkpoint
  inside_dies.resize(state.bodies.size());
  processes::broadcast(inside_dies);
  if (processes::root()) return;
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (H5Pset_fapl_core(access, 1 << 16, false) < 0 || H5Pset_file_image(access, image.data(), image.size()) < 0)
    throw RunError("cannot read the state rank 0 sent (HDF5 image)");
  Handle file(H5Fopen("state from rank 0", H5F_ACC_RDONLY, access), H5Fclose);
  if (!file.valid()) throw RunError("cannot read the state rank 0 sent (HDF5 image)");
  state = read_state(file, "the state rank 0 sent");
  state.inside_dies = std::move(inside_dies);
}

std::vector<std::string> read_checkpoint_fingerprint(const std::string& path) {
  silence();
  require_checkpoint_file(path);
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw InputError(path + ": not a readable HDF5 checkpoint (damaged, or not a checkpoint)");
  std::vector<std::string> lines;
  if (H5Lexists(file, "fingerprint", H5P_DEFAULT) <= 0) return lines; // written before format 5
  std::vector<char> text;
  read_array(file, path, "fingerprint", H5T_NATIVE_CHAR, text, 1);
  std::string line;
  for (char ch : text)
    if (ch == '\n')
      lines.push_back(std::move(line)), line.clear();
    else
      line += ch;
  return lines;
}

} // namespace anvil::io
