// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// shapecorr fit: the template fitted to one specimen, or to a batch in parallel (rigid alignment +
// NICPS, the template's connectivity kept). shapecorr ssm build | report | sample: a statistical
// shape model of fitted templates, its quality curves and modes, instances.
#include "cli_common.h"
#include "landmarks.h"

#include <shapecorr/io.h>
#include <shapecorr/parallel.h>
#include <shapecorr/shape_model.h>
#include <shapecorr/shape_model/fit_template.h>
#ifdef SHAPECORR_HAVE_HDF5
#include <shapecorr/shape_model/statismo_io.h>
#endif

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <nlohmann/json.hpp>

#include <boost/property_map/property_map.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <mutex>
#include <sstream>

namespace cli {
namespace {

nlohmann::json distance_json(const shapecorr::Surface_distance& d) { return {{"l1", d.l1}, {"l2", d.l2}, {"lmax", d.lmax}}; }

shapecorr::Statistical_shape_model load_model(const std::string& path);

// ---- fit --------------------------------------------------------------------------------------

struct Fit_job {
  std::size_t specimen = 0;          // positional index of the specimen
  std::string output, report;        // fitted mesh, JSON report (may be empty)
  std::string specimen_landmarks;    // landmark file of the specimen (may be empty)
};

// The template fitted to the specimen of `job`: writes the fitted mesh and the report; returns
// the summary line.
std::string fit_one(const Args& a, const Mesh& tmpl, const Landmarks& template_landmarks, const Fit_job& job, unsigned threads) {
  namespace SP = shapecorr::parameters;
  const Mesh specimen = read_mesh(a, job.specimen);
  const std::string& specimen_path = a.positional[job.specimen];
  Landmarks lt, ls = template_landmarks;
  if(!job.specimen_landmarks.empty()) {
    lt = read_landmarks(job.specimen_landmarks);
    pair_landmarks(ls, lt);
  }
  const std::string pre = a.get("pre-align", ls.points.empty() ? "pca" : "landmarks");
  shapecorr::Rigid_initialization init = shapecorr::Rigid_initialization::PRINCIPAL_AXES;
  if(pre == "landmarks") init = shapecorr::Rigid_initialization::LANDMARKS;
  else if(pre == "none") init = shapecorr::Rigid_initialization::NONE;
  std::vector<K::Point_3> fitted_points(num_vertices(tmpl));
  auto fitted = boost::make_iterator_property_map(fitted_points.begin(), get(boost::vertex_index, tmpl));
  const std::size_t iterations = to_count(a.get("iterations", "50"), "fit: --iterations", 1, 10000);
  const double max_pair =
      a.has("max-pair-distance") ? to_double(a.get("max-pair-distance"), "fit: --max-pair-distance", 0, 1e300, true) : std::numeric_limits<double>::infinity();
  const auto np1 = SP::rigid_initialization(init).allow_scaling(a.has("scale")).number_of_iterations(iterations).maximum_pair_distance(max_pair).number_of_threads(threads);
  const shapecorr::Template_fit_report r = ls.points.empty() ? shapecorr::fit_template(tmpl, specimen, fitted, np1)
                                                             : shapecorr::fit_template(tmpl, specimen, fitted, np1.landmark_points(ls.points), SP::landmark_points(lt.points));
  Mesh out = tmpl;
  for(vertex_descriptor v : vertices(out)) out.point(v) = fitted_points[v.idx()];
  if(!CGAL::IO::write_polygon_mesh(job.output, out, CGAL::parameters::stream_precision(17)))
    throw shapecorr::Output_error("fit: cannot write '" + job.output + "'");
  if(!job.report.empty()) {
    nlohmann::json j;
    j["template"] = a.positional[0];
    j["specimen"] = specimen_path;
    j["fitted"] = job.output;
    j["pre_align"] = pre;
    j["scale_allowed"] = a.has("scale");
    std::vector<std::vector<double>> m(4, std::vector<double>(4));
    const Eigen::Matrix4d M = r.rigid.transform.matrix();
    for(int i = 0; i < 4; ++i)
      for(int k = 0; k < 4; ++k) m[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = M(i, k);
    j["rigid_transform"] = m;
    j["rigid_stop"] = shapecorr::to_string(r.rigid.stop);
    j["nicps_stop"] = shapecorr::to_string(r.nicps.stop);
    j["nicps_iterations"] = r.nicps.iterations.size();
    j["distance_before"] = distance_json(r.before);
    j["distance_after_rigid"] = distance_json(r.after_rigid);
    j["distance_after"] = distance_json(r.after);
    if(!ls.points.empty()) {
      j["landmark_ids"] = ls.ids;
      j["landmark_vertices"] = r.landmark_vertices;
      j["landmark_distances_before"] = r.landmark_distances_before;
      j["landmark_distances_after_rigid"] = r.landmark_distances_after_rigid;
      j["landmark_distances_after"] = r.landmark_distances_after;
    }
    j["seconds"] = r.seconds;
    std::ofstream o = open_output(job.report);
    o << j.dump(2) << "\n";
  }
  std::ostringstream line;
  line << specimen_path << ": l2 " << r.after_rigid.l2 << " (rigid) -> " << r.after.l2 << ", lmax " << r.after.lmax;
  if(!r.landmark_distances_after.empty()) {
    double mean = 0;
    for(double d : r.landmark_distances_after) mean += d / static_cast<double>(r.landmark_distances_after.size());
    line << ", mean landmark distance " << mean;
  }
  line << ", " << r.nicps.iterations.size() << " NICPS iterations, " << std::fixed << std::setprecision(1) << r.seconds << " s -> " << job.output;
  return line.str();
}

// The template: a mesh, or the mean shape of a model (.ssm, .h5) with its connectivity.
Mesh read_template(const Args& a) {
  const std::string ext = extension(a.positional[0]);
  if(ext != "ssm" && ext != "h5") return read_mesh(a, 0);
  Mesh m;
  const shapecorr::Statistical_shape_model model = load_model(a.positional[0]);
  shapecorr::make_shape_mesh(model, model.mean(), m);
  return m;
}

int run_fit(const Args& a) {
  const Mesh tmpl = read_template(a);
  const std::size_t count = a.positional.size() - 1;
  if(a.has("output") == a.has("output-dir")) throw Usage_error("fit: give --output FILE (one specimen) or --output-dir DIR (one or more)");
  if(a.has("output") && count != 1) throw Usage_error("fit: --output takes one specimen; for " + std::to_string(count) + " use --output-dir DIR");
  if(a.has("report") && count != 1) throw Usage_error("fit: --report takes one specimen; with --output-dir each fit's report is DIR/NAME.json");
  if(a.has("landmarks") && a.has("template-landmarks")) throw Usage_error("fit: give --landmarks T S or --template-landmarks T, not both");
  if(a.has("landmarks") && count != 1) throw Usage_error("fit: --landmarks T S takes one specimen; for several use --template-landmarks T");
  const std::string pre = a.get("pre-align", "pca");
  if(pre != "pca" && pre != "landmarks" && pre != "none") throw Usage_error("fit: --pre-align must be pca, landmarks or none");
  if(pre == "landmarks" && !a.has("landmarks") && !a.has("template-landmarks"))
    throw Usage_error("fit: --pre-align landmarks needs --landmarks T S or --template-landmarks T");
  if(a.has("output")) {
    const std::string ext = extension(a.get("output"));
    if(ext != "ply" && ext != "off" && ext != "obj" && ext != "stl") throw Usage_error("fit: --output must end in .ply, .off, .obj or .stl");
  }
  to_count(a.get("iterations", "50"), "fit: --iterations", 1, 10000); // checked before any work
  const unsigned threads = static_cast<unsigned>(to_count(a.get("threads", "0"), "fit: --threads", 0, 1024));

  Landmarks template_landmarks;
  std::vector<Fit_job> jobs;
  if(a.has("landmarks")) template_landmarks = read_landmarks(a.values("landmarks")[0]);
  if(a.has("template-landmarks")) template_landmarks = read_landmarks(a.get("template-landmarks"));
  for(std::size_t i = 1; i <= count; ++i) {
    Fit_job job;
    job.specimen = i;
    const std::filesystem::path specimen(a.positional[i]);
    if(a.has("output")) {
      job.output = a.get("output");
      job.report = a.get("report");
    } else {
      const std::filesystem::path dir(a.get("output-dir"));
      std::filesystem::create_directories(dir);
      job.output = (dir / (specimen.stem().string() + ".ply")).string();
      job.report = (dir / (specimen.stem().string() + ".json")).string();
    }
    if(a.has("landmarks")) job.specimen_landmarks = a.values("landmarks")[1];
    if(a.has("template-landmarks")) {
      std::filesystem::path beside = specimen;
      beside.replace_extension(".json");
      if(!std::filesystem::exists(beside))
        throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, "fit: " + beside.string() + ": no landmark file beside the specimen");
      job.specimen_landmarks = beside.string();
    }
    jobs.push_back(job);
  }
  // a batch: fits in parallel, one thread each; one fit: all threads inside it
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(shapecorr::resolve_thread_count(threads), jobs.size()));
  const unsigned inner = workers > 1 ? 1u : threads;
  std::mutex print;
  std::size_t done = 0;
  const auto t0 = std::chrono::steady_clock::now();
  shapecorr::parallel_for(jobs.size(), workers, [&](std::size_t i, unsigned) {
    const std::string line = fit_one(a, tmpl, template_landmarks, jobs[i], inner);
    std::lock_guard<std::mutex> lock(print);
    ++done;
    if(verbose(a)) std::cerr << "fit: " << done << "/" << jobs.size() << " " << line << "\n";
  });
  if(verbose(a) && jobs.size() > 1)
    std::cerr << "fit: " << jobs.size() << " specimens, " << workers << " at a time, " << std::fixed << std::setprecision(1) << seconds_since(t0) << " s\n";
  return 0;
}

// ---- ssm -------------------------------------------------------------------------------------

shapecorr::Statistical_shape_model load_model(const std::string& path) {
  if(extension(path) == "h5") {
#ifdef SHAPECORR_HAVE_HDF5
    return shapecorr::read_statismo_model(path);
#else
    throw Usage_error("ssm: '" + path + "': this shapecorr was built without HDF5 (libhdf5-dev): Statismo .h5 files are not read");
#endif
  }
  return shapecorr::Statistical_shape_model::load(path);
}

void check_model_extension(const std::string& path) {
  const std::string ext = extension(path);
  if(ext != "ssm" && ext != "h5") throw Usage_error("ssm: MODEL must end in .ssm (ShapeCorr's file) or .h5 (the Statismo HDF5 layout)");
#ifndef SHAPECORR_HAVE_HDF5
  if(ext == "h5") throw Usage_error("ssm: this shapecorr was built without HDF5 (libhdf5-dev): use a .ssm file");
#endif
}

int run_ssm_build(const Args& a) {
  const std::string output = a.require("output");
  check_model_extension(output);
  std::vector<Mesh> meshes;
  std::vector<std::string> names;
  for(std::size_t i = 0; i < a.positional.size(); ++i) {
    meshes.push_back(read_mesh(a, i));
    names.push_back(std::filesystem::path(a.positional[i]).filename().string());
  }
  const auto t0 = std::chrono::steady_clock::now();
  shapecorr::Statistical_shape_model model = shapecorr::build_statistical_shape_model(meshes, shapecorr::parameters::allow_scaling(a.has("scale")));
  model.set_training_names(names);
  if(extension(output) == "h5") {
#ifdef SHAPECORR_HAVE_HDF5
    shapecorr::write_statismo_model(model, output);
#endif
  } else {
    model.save(output);
  }
  if(verbose(a)) {
    const Eigen::VectorXd r = model.explained_variance_ratios();
    std::cerr << "ssm build: " << meshes.size() << " shapes of " << model.number_of_vertices() << " vertices, " << model.number_of_modes() << " modes ("
              << (a.has("scale") ? "similarity" : "rigid") << " Procrustes); explained variance";
    for(Eigen::Index i = 0; i < std::min<Eigen::Index>(3, r.size()); ++i) std::cerr << " PC" << i + 1 << " " << std::setprecision(3) << 100 * r[i] << " %";
    std::cerr << "; " << std::setprecision(3) << seconds_since(t0) << " s -> " << output << "\n";
  }
  return 0;
}

// The mesh of `shape` coloured by each vertex's distance to the same vertex of `reference` (the
// values as the PLY's quality).
void write_displacement_ply(const std::string& path, const shapecorr::Statistical_shape_model& model, const Eigen::VectorXd& shape,
                            const Eigen::VectorXd& reference, std::vector<double>* values_out = nullptr) {
  Mesh m;
  shapecorr::make_shape_mesh(model, shape, m);
  std::vector<double> values(model.number_of_vertices());
  for(std::size_t i = 0; i < values.size(); ++i) values[i] = (shape.segment(3 * static_cast<Eigen::Index>(i), 3) - reference.segment(3 * static_cast<Eigen::Index>(i), 3)).norm();
  shapecorr::write_colored_ply(path, m, values);
  if(values_out) *values_out = values;
}

int run_ssm_report(const Args& a) {
  const shapecorr::Statistical_shape_model model = load_model(a.positional[0]);
  const std::filesystem::path dir(a.require("output"));
  const std::size_t show = to_count(a.get("modes", "3"), "ssm report: --modes", 0, 1000);
  const std::size_t samples = to_count(a.get("samples", "1000"), "ssm report: --samples", 1, 1000000);
  const unsigned seed = static_cast<unsigned>(to_count(a.get("seed", "0"), "ssm report: --seed", 0, 4294967295u));
  std::filesystem::create_directories(dir);
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t k = model.number_of_modes(), N = model.number_of_training_shapes();
  const shapecorr::Shape_model_curve C = shapecorr::shape_model_compactness(model);
  const bool measures = model.keeps_all_variance() && N >= 3;
  shapecorr::Shape_model_curve G, S;
  if(measures) {
    const bool show_progress = verbose(a);
    G = shapecorr::shape_model_generalization(model, shapecorr::parameters::progress_callback(std::function<void(std::size_t, std::size_t)>([&](std::size_t d, std::size_t n) {
      if(show_progress) std::cerr << "ssm report: generalization, left out " << d << "/" << n << "\n";
    })));
    S = shapecorr::shape_model_specificity(model, shapecorr::parameters::number_of_samples(samples).random_seed(seed));
  } else if(verbose(a)) {
    std::cerr << "ssm report: the model keeps " << N << " training shapes" << (model.keeps_all_variance() ? "" : " and not all their variance")
              << ": generalization and specificity need 3 or more, all variance kept\n";
  }
  // the curves: CSV and pictures
  {
    std::ofstream csv = open_output((dir / "quality.csv").string());
    csv << "modes,compactness,compactness_fraction,compactness_se,generalization,generalization_se,specificity,specificity_se\n";
    for(std::size_t m = 1; m <= k; ++m) {
      csv << m << "," << C.value[m - 1] << "," << C.value[m - 1] / model.total_variance() << "," << C.standard_error[m - 1];
      auto cell = [&](const shapecorr::Shape_model_curve& c) {
        if(m <= c.value.size()) csv << "," << c.value[m - 1] << "," << c.standard_error[m - 1];
        else csv << ",,";
      };
      cell(G);
      cell(S);
      csv << "\n";
    }
  }
  auto plot = [&](const std::string& name, const shapecorr::Shape_model_curve& c, double scale, const std::string& title, const std::string& ylabel) {
    if(c.value.empty()) return;
    shapecorr::Plot_curve value{"MEAN", {}, {}}, low{"-1 SE", {}, {}}, high{"+1 SE", {}, {}};
    double top = 0;
    for(std::size_t m = 0; m < c.value.size(); ++m) {
      const double x = static_cast<double>(m + 1);
      value.x.push_back(x), low.x.push_back(x), high.x.push_back(x);
      value.y.push_back(c.value[m] * scale), low.y.push_back((c.value[m] - c.standard_error[m]) * scale), high.y.push_back((c.value[m] + c.standard_error[m]) * scale);
      top = std::max(top, (c.value[m] + c.standard_error[m]) * scale);
    }
    const double ymax = top > 0 ? std::pow(10.0, std::ceil(std::log10(top) * 4) / 4) : 1.0;
    shapecorr::write_png((dir / (name + ".png")).string(),
                         shapecorr::line_plot({value, low, high}, title, "NUMBER OF MODES M", ylabel, static_cast<double>(c.value.size()), ymax));
  };
  shapecorr::Shape_model_curve fraction = C;
  for(auto& v : fraction.value) v /= model.total_variance();
  for(auto& v : fraction.standard_error) v /= model.total_variance();
  plot("compactness", fraction, 1.0, "COMPACTNESS C(M) / TOTAL VARIANCE", "FRACTION");
  plot("generalization", G, 1.0, "GENERALIZATION G(M), LEAVE-ONE-OUT: MEAN VERTEX DISTANCE", "DISTANCE");
  plot("specificity", S, 1.0, "SPECIFICITY S(M): MEAN VERTEX DISTANCE", "DISTANCE");
  // the first modes at -3, 0, +3 standard deviations, coloured by the displacement from the mean
  const std::size_t modes = std::min(show, k);
  nlohmann::json mode_files = nlohmann::json::array();
  for(std::size_t i = 0; i < modes; ++i) {
    nlohmann::json files;
    for(int sd : {-3, 0, 3}) {
      Eigen::VectorXd c = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(i + 1));
      c[static_cast<Eigen::Index>(i)] = sd;
      const std::string name = "mode" + std::to_string(i + 1) + (sd < 0 ? "_minus3sd" : sd > 0 ? "_plus3sd" : "_mean");
      std::vector<double> values;
      const Eigen::VectorXd x = model.instance(c);
      write_displacement_ply((dir / (name + ".ply")).string(), model, x, model.mean(), &values);
      if(sd != 0) {
        Mesh m;
        shapecorr::make_shape_mesh(model, x, m);
        shapecorr::Mesh_picture_options o;
        o.title = "MODE " + std::to_string(i + 1) + (sd < 0 ? " AT -3 SD" : " AT +3 SD") + ": DISPLACEMENT FROM THE MEAN";
        shapecorr::write_colored_mesh_png((dir / (name + ".png")).string(), m, values, o);
      }
      files[sd < 0 ? "minus3sd" : sd > 0 ? "plus3sd" : "mean"] = name + ".ply";
    }
    mode_files.push_back(files);
  }
  nlohmann::json j;
  j["model"] = a.positional[0];
  j["vertices"] = model.number_of_vertices();
  j["triangles"] = model.triangles().size();
  j["training_shapes"] = N;
  j["training_names"] = model.training_names();
  j["with_scale"] = model.with_scale();
  j["modes"] = k;
  j["total_variance"] = model.total_variance();
  std::vector<double> variances(model.variances().data(), model.variances().data() + k);
  j["variances"] = variances;
  const Eigen::VectorXd ratios = model.explained_variance_ratios();
  j["explained_variance_ratios"] = std::vector<double>(ratios.data(), ratios.data() + k);
  j["compactness"] = C.value;
  j["generalization"] = {{"value", G.value}, {"standard_error", G.standard_error}, {"per_shape", G.per_sample}};
  j["specificity"] = {{"value", S.value}, {"standard_error", S.standard_error}, {"samples", samples}, {"seed", seed}};
  if(N > 0) {
    std::vector<std::vector<double>> scores;
    for(std::size_t s = 0; s < N; ++s) {
      const auto col = model.training_scores().col(static_cast<Eigen::Index>(s));
      scores.emplace_back(col.data(), col.data() + k);
    }
    j["training_scores"] = scores;
  }
  j["mode_meshes"] = mode_files;
  j["seconds"] = seconds_since(t0);
  {
    std::ofstream o = open_output((dir / "summary.json").string());
    o << j.dump(2) << "\n";
  }
  if(verbose(a)) {
    std::cerr << "ssm report: " << N << " shapes, " << k << " modes; explained variance";
    for(Eigen::Index i = 0; i < std::min<Eigen::Index>(3, ratios.size()); ++i) std::cerr << " PC" << i + 1 << " " << std::setprecision(3) << 100 * ratios[i] << " %";
    if(!G.value.empty()) std::cerr << "; G(1) " << G.value[0] << ", S(1) " << S.value[0];
    std::cerr << "; " << std::setprecision(3) << seconds_since(t0) << " s -> " << dir.string() << "/\n";
  }
  return 0;
}

int run_ssm_sample(const Args& a) {
  const shapecorr::Statistical_shape_model model = load_model(a.positional[0]);
  const std::string output = a.require("output");
  const std::string ext = extension(output);
  if(ext != "ply" && ext != "off" && ext != "obj" && ext != "stl") throw Usage_error("ssm sample: --output must end in .ply, .off, .obj or .stl");
  std::vector<double> c;
  std::stringstream list(a.require("coefficients"));
  std::string item;
  while(std::getline(list, item, ',')) c.push_back(to_double(item, "ssm sample: --coefficients", -1e6, 1e6));
  if(c.size() > model.number_of_modes())
    throw Usage_error("ssm sample: " + std::to_string(c.size()) + " coefficients for a model of " + std::to_string(model.number_of_modes()) + " modes");
  const Eigen::VectorXd x = model.instance(Eigen::Map<const Eigen::VectorXd>(c.data(), static_cast<Eigen::Index>(c.size())));
  if(ext == "ply" && a.has("colored")) {
    write_displacement_ply(output, model, x, model.mean());
  } else {
    Mesh m;
    shapecorr::make_shape_mesh(model, x, m);
    if(!CGAL::IO::write_polygon_mesh(output, m, CGAL::parameters::stream_precision(17))) throw shapecorr::Output_error("ssm sample: cannot write '" + output + "'");
  }
  if(verbose(a)) std::cerr << "ssm sample: " << c.size() << " of " << model.number_of_modes() << " coefficients -> " << output << "\n";
  return 0;
}

} // namespace

const Command& fit_command() {
  static const Command c{
      "fit",
      "fit TEMPLATE SPECIMEN... (--output FITTED.ply | --output-dir DIR) [--landmarks T S | --template-landmarks T] [--report R.json] [options]",
      "Fits TEMPLATE (a mesh, or a shape model, .ssm or .h5, whose mean shape is the template) to each SPECIMEN (thesis chapter 6): "
      "a rigid alignment (principal axes and ICP, or landmark pairs), then NICPS. "
      "The fitted template keeps TEMPLATE's vertices and faces, so the fits of one template are in correspondence: the input of "
      "'shapecorr ssm build'. One specimen: --output FILE (.ply, .off, .obj, .stl) and --report FILE.json. Several: --output-dir DIR "
      "gets NAME.ply and NAME.json per specimen, fits run in parallel (--threads). Reports: the rigid transform, the surface distances "
      "(l1, l2, lmax) before, after the rigid alignment and after NICPS, the landmark distances. A line per fit on stderr.",
      with_mesh_reading_options({{"output", "FILE", "the fitted template (one specimen)"},
                                 {"output-dir", "DIR", "the fitted templates and reports, NAME.ply and NAME.json per specimen"},
                                 {"report", "FILE.json", "the fit's report (one specimen)"},
                                 {"landmarks", "T S", "landmark files of TEMPLATE and of SPECIMEN (JSON or text; paired by id, else by order)"},
                                 {"template-landmarks", "T", "TEMPLATE's landmarks; each specimen's are in the .json file beside it"},
                                 {"pre-align", "pca|landmarks|none", "initialization (default pca, landmarks with landmark files)"},
                                 {"scale", "", "the rigid alignment also scales (a similarity)"},
                                 {"iterations", "N", "bound of ICP per start and of NICPS (50)"},
                                 {"max-pair-distance", "D", "NICPS drops pairs longer than D (mesh units; default none)"},
                                 {"threads", "N", "fits at a time (several specimens) or threads of one fit (0: all cores, default)"}}),
      2, 100000, run_fit};
  return c;
}

const Command& ssm_build_command() {
  static const Command c{
      "ssm build",
      "ssm build FITTED... --output MODEL.ssm|MODEL.h5 [--scale]",
      "A statistical shape model of meshes in correspondence (the fits of one template, 'shapecorr fit'): generalized Procrustes "
      "alignment (rigid, or with --scale similarities), the mean, PCA through the N x N Gram matrix. MODEL: .ssm (ShapeCorr's binary "
      "file, doubles) or .h5 (the Statismo HDF5 layout, opens in Statismo and Scalismo; builds with HDF5). Prints the explained variance "
      "of the first modes.",
      with_mesh_reading_options({{"output", "MODEL", "the model, .ssm or .h5"}, {"scale", "", "Procrustes alignment with a uniform scale"}}),
      2, 100000, run_ssm_build};
  return c;
}

const Command& ssm_report_command() {
  static const Command c{
      "ssm report",
      "ssm report MODEL --output DIR [--modes 3] [--samples 1000] [--seed 0]",
      "The quality of a shape model (.ssm or .h5) in DIR: compactness C(M) (cumulative variance), generalization G(M) (leave-one-out: "
      "each training shape rebuilt by the model of the others with M modes, mean vertex distance) and specificity S(M) (random "
      "instances with M modes to their nearest training shape, mean vertex distance), each with its standard error, as quality.csv and "
      "PNG plots; the first modes at -3, 0 and +3 standard deviations as PLY meshes coloured by the displacement from the mean, with "
      "pictures; summary.json (variances, explained fractions, curves, training scores).",
      {{"output", "DIR", "the report's folder"},
       {"modes", "K", "modes shown as meshes (default 3)"},
       {"samples", "K", "random instances of the specificity (default 1000)"},
       {"seed", "S", "seed of the specificity's instances (default 0)"},
       {"quiet", "", "no progress on stderr"}},
      1, 1, run_ssm_report};
  return c;
}

const Command& ssm_sample_command() {
  static const Command c{
      "ssm sample",
      "ssm sample MODEL --coefficients c1,c2,... --output X.ply [--colored]",
      "An instance of a shape model: the mean plus c_i standard deviations along mode i (the first coefficients given, the others 0), "
      "written with the model's connectivity (.ply, .off, .obj, .stl).",
      {{"coefficients", "c1,c2,...", "coefficients in standard deviations"},
       {"output", "FILE", "the instance's mesh"},
       {"colored", "", "a .ply coloured by each vertex's displacement from the mean"},
       {"quiet", "", "no summary on stderr"}},
      1, 1, run_ssm_sample};
  return c;
}

} // namespace cli
