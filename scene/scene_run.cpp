#include "scene/scene_run.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/stopwatch.h"
#include "timing/bench.h"
#include "inspect/html_report.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "inspect/mapped_mesh.h"
#include "inspect/mesh_view.h"
#include "render/shading.h"
#include "inspect/run_report.h"
#include "io/json_text.h"

namespace uvtk::scene {

using namespace uvtk::inspect;
using namespace uvtk::timing;

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The overlap raster of the judgement the views, the OBJ summaries and the gallery read
// (MappedMesh::judge's default: the raster follows the mesh).
constexpr int kViewsOverlapResolution = analysis::kOverlapFollowsMesh;

// The faces each 3D view of the gallery shows before it decimates: the page holds every report's.
constexpr std::size_t kGalleryViewFaces = 50000;

// A verdict's reasons as the gallery shows them: each one's severity and text.
json reasonsRecord(const analysis::Judgement& judgement) {
  json reasons = json::array();
  for (const analysis::Reason& r : judgement.reasons) reasons.push_back({{"severity", toString(r.severity)}, {"text", r.text()}});
  return reasons;
}

// The verdict and its reasons (the first alone too) of a mapping, for the run report and the gallery.
void addVerdict(json& record, const analysis::Judgement& judgement) {
  record["verdict"] = analysis::toString(judgement.verdict);
  record["first_reason"] = judgement.firstReason();
  record["reasons"] = reasonsRecord(judgement);
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

const TextureSettings& textureOf(const Scene& scene, std::size_t index) {
  return index < scene.textures.size() ? scene.textures[index].settings : scene.defaultTexture;
}

// The names of what `frame` draws: views, or AOVs ("uv" for the channels u and v).
std::string viewNames(const FrameOptions& frame) {
  std::string names;
  for (const views::View view : frame.views) names += (names.empty() ? "" : ",") + std::string(views::toString(view));
  return names;
}
std::string aovNames(const FrameOptions& frame) {
  std::string names;
  for (const std::string& channel : frame.aovs)
    if (channel != "v") names += (names.empty() ? "" : ",") + (channel == "u" ? std::string("uv") : channel);
  return names;
}

// What a render output computes beyond rasterising the mesh with its texture coordinates.
std::vector<std::string> renderComputes(const Scene& scene, const SceneOutput& o) {
  const SceneMapping& mapping = scene.mappings[*o.mapping];
  const FrameOptions& f = o.frame.frame;
  std::vector<std::string> computes;
  if (!f.views.empty()) computes.push_back("views " + viewNames(f));
  if (f.needsExact()) computes.push_back("exact UVs per pixel");
  if (f.views.empty()) {
    const bool lit = render::readsFragmentColour(textureOf(scene, o.texture.value_or(scene.textures.size())).env);
    if (lit) computes.push_back("lighting (corner normals)");
    if (!lit && f.perPixel && mapping.needsNormals()) computes.push_back("corner normals");
    if (f.samplesPerPixel > 1) computes.push_back(std::to_string(f.samplesPerPixel) + " samples per pixel");
    if (!f.aovs.empty()) computes.push_back("AOVs " + aovNames(f));
  }
  return computes;
}

// What a bench output times: the configurations of the mapping kernel, each for at least min_time.
std::vector<std::string> benchComputes(const BenchOptions& b) {
  std::size_t configurations = 0;
  for (const BenchProjector& p : b.projectors) {
    const bool wraps =
        param::traitsOf(p.options.surface).wraps;
    configurations += b.precisions.size() * (wraps ? b.maths.size() : 1) * b.threads.size();
  }
  char text[96];
  std::snprintf(text, sizeof text, "the mapping kernel: %zu configurations, %g s each", configurations, b.minTime);
  std::vector<std::string> computes = {text, "the long-double reference"};
  if (b.peers) computes.push_back("the peers");
  return computes;
}

// A usage error while running is a problem of the scene's content, so bad input.
int statusOf(const std::exception& e) { return exitStatus(e) == 2 ? 3 : exitStatus(e); }

// The state of one mesh's stages: the mesh as read, its mappings, their measures.
struct MeshWork {
  io::ReadMeshResult input;
  json inputSummary;
  std::map<std::size_t, MappedMesh> mapped;
  std::map<std::pair<std::size_t, int>, analysis::Judgement> judgements;
};

class SceneRunner {
 public:
  SceneRunner(const Scene& scene, const std::vector<Stage>& plan) : scene_(scene), plan_(plan) {
    records_ = planJson(scene, plan)["stages"];
    for (json& record : records_) record["status"] = "not run";
    outputs_.resize(scene.outputs.size());
    views3d_.resize(scene.outputs.size());
  }

  RunResult run(const RunOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    createFolders();
    Progress progress("uvtk run", plan_.size(), "stages");
    progress_ = &progress;
    // Textures first: shared by every mesh's renders.
    std::vector<std::size_t> shared, last;
    std::vector<std::size_t> groupOrder;
    std::map<std::size_t, std::vector<std::size_t>> groups;
    std::vector<std::size_t> timed;  // benchmarks: alone, so that nothing else runs beside them
    for (std::size_t i = 0; i < plan_.size(); ++i) {
      if (plan_[i].kind == Stage::Kind::Bench) {
        timed.push_back(i);
      } else if (plan_[i].mesh) {
        if (!groups.count(*plan_[i].mesh)) groupOrder.push_back(*plan_[i].mesh);
        groups[*plan_[i].mesh].push_back(i);
      } else {
        (plan_[i].kind == Stage::Kind::Texture ? shared : last).push_back(i);
      }
    }
    runStages(shared, nullptr, "textures");
    parallelFor(int(groupOrder.size()), options.jobs, [&](int g) {
      MeshWork work;
      runStages(groups[groupOrder[std::size_t(g)]], &work, scene_.meshes[groupOrder[std::size_t(g)]].name);
    });
    runStages(timed, nullptr, "bench");
    publishOutputs();
    runStages(last, nullptr, "gallery");
    publishOutputs();
    progress.finish();
    progress_ = nullptr;

    RunResult result;
    result.status = status_;
    result.report = {{"tool", {{"name", "uvtk"}, {"version", UVTK_VERSION}}},
                     {"scene", scene_.path},
                     {"title", scene_.title},
                     {"status", failures_.empty() ? "ok" : "failed"},
                     {"stages", records_},
                     {"outputs", outputsJson()},
                     {"failures", failures_},
                     {"milliseconds", {{"total", millisecondsSince(start)}}}};
    return result;
  }

 private:
  void createFolders() const {
    for (const SceneOutput& o : scene_.outputs)
      for (const std::string& file : o.files()) {
        const fs::path folder = fs::path(file).parent_path();
        std::error_code error;
        if (!folder.empty()) fs::create_directories(folder, error);
        if (error) throw OutputError(file + ": error: cannot create the folder: " + error.message());
      }
  }

  // The outputs of the stages that succeeded, all at once. A scene's outputs are staged as their
  // stages run and published together when every mesh is done, so that an interrupted run or a
  // failed publish leaves none of them (and the previous versions); the outputs of a stage that
  // fails are dropped with it (an OBJ never appears without its summary), while the other stages'
  // are published, as a failing mesh does not stop the others. Each staged output holds an open
  // file until then (one descriptor each). The gallery, which links only the files that are in
  // place, is written after them and published alone; the run report (--json) after that, since
  // it records how publishing went.
  void publishOutputs() {
    try {
      staged_.publish();
    } catch (const std::exception& e) {
      printProgressMessage(e.what());
      failures_.push_back({{"group", "outputs"}, {"stage", "publish"}, {"subject", ""}, {"message", e.what()}});
      status_ = std::max(status_, statusOf(e));
    }
  }

  // Runs `stages` one after another; a stage whose needs did not all succeed is skipped.
  void runStages(const std::vector<std::size_t>& stages, MeshWork* work, const std::string& group) {
    for (const std::size_t i : stages) {
      const auto start = std::chrono::steady_clock::now();
      progress_->advance();
      const std::vector<std::size_t>& needs = plan_[i].needs;
      if (std::any_of(needs.begin(), needs.end(), [&](std::size_t n) { return records_[n]["status"] != "ok"; })) {
        records_[i]["status"] = "skipped";
        continue;
      }
      try {
        io::OutputSet outputs;
        runStage(plan_[i], work, outputs);
        staged_.adopt(outputs);
        records_[i]["status"] = "ok";
        records_[i]["milliseconds"] = millisecondsSince(start);
      } catch (const std::exception& e) {
        records_[i]["status"] = "failed";
        const std::string message = messageOf(plan_[i], e);
        printProgressMessage(message);
        std::lock_guard<std::mutex> lock(mutex_);
        failures_.push_back(
            {{"group", group}, {"stage", records_[i]["stage"]}, {"subject", plan_[i].subject}, {"message", message}});
        status_ = std::max(status_, statusOf(e));
      }
    }
  }

  // A usage error of a stage (the file's UVs missing, say) is reported at the scene entry it comes from.
  std::string messageOf(const Stage& stage, const std::exception& e) const {
    if (!dynamic_cast<const UsageError*>(&e)) return errorMessage(e);
    std::string pointer;
    if (stage.kind == Stage::Kind::Map || stage.kind == Stage::Kind::Measure)
      pointer = scene_.mappings[stage.index].pointer;
    if (stage.kind >= Stage::Kind::Mesh) pointer = scene_.outputs[stage.index].pointer;
    if (stage.kind == Stage::Kind::Texture && stage.index < scene_.textures.size())
      pointer = scene_.textures[stage.index].pointer;
    return scene_.path + ": " + (pointer.empty() ? "" : pointer + ": ") + e.what();
  }

  void runStage(const Stage& stage, MeshWork* work, io::OutputSet& outputs) {
    switch (stage.kind) {
      case Stage::Kind::Texture:
        textures_.insert_or_assign(stage.index, textureOf(scene_, stage.index).load());
        return;
      case Stage::Kind::Read:
        work->input = io::readMesh(scene_.meshes[stage.index].path);
        work->inputSummary = inputJson(scene_.meshes[stage.index].path, work->input);
        printInputWarnings(scene_.meshes[stage.index].path, work->input.warnings);
        return;
      case Stage::Kind::Map:
        work->mapped.emplace(stage.index, map(scene_.mappings[stage.index], *work));
        return;
      case Stage::Kind::Measure:
        work->judgements[{stage.index, stage.overlapResolution}] =
            work->mapped.at(stage.index).judge(scene_.thresholds, stage.overlapResolution);
        return;
      case Stage::Kind::Mesh:
        return writeMesh(outputs, scene_.outputs[stage.index], stage.index, *work);
      case Stage::Kind::Render:
        return renderOutput(outputs, scene_.outputs[stage.index], stage.index, *work);
      case Stage::Kind::Report: {
        const SceneOutput& o = scene_.outputs[stage.index];
        const MappedMesh& mapped = work->mapped.at(*o.mapping);
        const ReportOptions& options = o.report;
        const analysis::Judgement& judgement = judgementFor(work->judgements.at({*o.mapping, o.report.overlapResolution}),
                                                            mapped, o.report.overlapResolution, options.textureSize);
        const json report = writeReport(outputs, options, mapped, judgement, work->inputSummary);
        outputs_[stage.index] = {{"mapping", scene_.mappings[*o.mapping].name},
                                 {"verdict", report["verdict"]},
                                 {"first_reason", judgement.firstReason()},
                                 {"reasons", reasonsRecord(judgement)},
                                 {"mesh", scene_.meshes[scene_.mappings[*o.mapping].mesh].name},
                                 {"stretch_l2", report["stretch_l2"]},
                                 {"stretch_linf", report["stretch_linf"]},
                                 {"angle_mean", report["angle"]["mean"]},
                                 {"seam_length", report["seams"]["length"]},
                                 {"overlap_fraction", report["overlap_fraction"]}};
        if (hasGallery()) {
          MeshViewOptions view;
          view.faceBudget = std::min<std::size_t>(o.report.view3dFaces, kGalleryViewFaces);
          view.camera = o.report.camera;
          if (view.faceBudget > 0) views3d_[stage.index] = meshViewHtml(mapped, judgement, view);
        }
        return;
      }
      case Stage::Kind::Compare: {
        const SceneOutput& o = scene_.outputs[stage.index];
        CompareOptions options = o.compare;
        options.thresholds = scene_.thresholds;
        const Comparison comparison = compareMappings(outputs, options, work->input.mesh, work->inputSummary);
        json top = json::array();
        for (const json& r : comparison.record["ranking"]) {
          if (top.size() == 5) break;
          top.push_back({{"rank", r["rank"]},
                         {"name", r["name"]},
                         {"stretch_l2", r["stretch_l2"]},
                         {"verdict", r["verdict"]},
                         {"first_reason", r["first_reason"]}});
        }
        outputs_[stage.index] = {{"mesh", scene_.meshes[*o.mesh].name}, {"best", comparison.best}, {"top", top}};
        return;
      }
      case Stage::Kind::Bench: {
        const SceneOutput& o = scene_.outputs[stage.index];
        const BenchResult result = measureBench(o.bench);
        writeBenchOutputs(outputs, o.bench, result);
        const std::size_t mesh = o.mapping ? scene_.mappings[*o.mapping].mesh : *o.mesh;
        // What the gallery shows: the mapping's chart inline.
        json record = {{"mesh", scene_.meshes[mesh].name},
                       {"configurations", result.mapping.points.size()},
                       {"title", result.mapping.options.title},
                       {"svg", result.mappingSvg}};
        if (o.mapping) record["mapping"] = scene_.mappings[*o.mapping].name;
        outputs_[stage.index] = record;
        return;
      }
      case Stage::Kind::Gallery: {
        const SceneOutput& o = scene_.outputs[stage.index];
        json report = {{"title", o.title},
                       {"scene", scene_.path},
                       {"stages", records_},
                       {"outputs", outputsJson()},
                       {"failures", failures_}};
        std::vector<std::pair<std::string, std::string>> views;
        for (std::size_t i = 0; i < views3d_.size(); ++i)
          if (!views3d_[i].empty())
            views.emplace_back(outputs_[i].value("mapping", std::string()) + " (" + outputs_[i].value("mesh", std::string()) +
                                   "): " + outputs_[i].value("verdict", std::string()),
                               views3d_[i]);
        outputs.writeText(o.path, galleryHtml(report, o.path, views));
        return;
      }
    }
  }

  // The planned judgement, or where the output counts texel density in another texture size than
  // the plan's 1024 x 1024, a judgement of its own (kept until the run ends).
  const analysis::Judgement& judgementFor(const analysis::Judgement& planned, const MappedMesh& mapped,
                                          int overlapResolution, const analysis::TextureSize& textureSize) {
    if (planned.summary.density.textureSize == textureSize) return planned;
    std::lock_guard<std::mutex> lock(ownJudgementsMutex_);
    return ownJudgements_.emplace_back(mapped.judge(scene_.thresholds, overlapResolution, 0, textureSize));
  }

  bool hasGallery() const {
    return std::any_of(scene_.outputs.begin(), scene_.outputs.end(),
                       [](const SceneOutput& o) { return o.kind == SceneOutput::Kind::Gallery; });
  }

  MappedMesh map(const SceneMapping& m, const MeshWork& work) const {
    Mesh mesh = work.input.mesh;
    switch (m.kind) {
      case SceneMapping::Kind::Projector:
        return mapByProjector(std::move(mesh), m.projector, m.seamPlaceAuto);
      case SceneMapping::Kind::Texgen: {
        const Mat4& model = scene_.meshes[m.mesh].model;
        // A camera's view as framed for a 512 x 512 picture (framing depends on the aspect only through the distance).
        const Mat4 view = m.camera ? Mat4(scene_.cameras[*m.camera].settings.make(mesh, scene_.meshes[m.mesh].path, model, 512, 512).viewFromWorld)
                                   : m.viewFromWorld;
        return mapByTexgen(std::move(mesh), texgen::drawnUnder(m.texgen, view, model));
      }
      case SceneMapping::Kind::File:
        break;
    }
    return withFileUvs(std::move(mesh), scene_.meshes[m.mesh].path);
  }

  void writeMesh(io::OutputSet& outputs, const SceneOutput& o, std::size_t index, const MeshWork& work) {
    const MappedMesh& mapped = work.mapped.at(*o.mapping);
    io::MeshWriteOptions write = o.write;
    write.header = "uvtk run " + scene_.path + ": mapping " + scene_.mappings[*o.mapping].name;
    io::writeMesh(outputs, o.path, mapped.mesh, &mapped.uv, write);
    const analysis::Judgement& judgement = work.judgements.at({*o.mapping, kViewsOverlapResolution});
    const json summary = mapSummaryJson(mapped, judgement, work.inputSummary, o.path);  // as `uvtk map --json`
    if (!o.json.empty()) outputs.writeText(o.json, io::jsonText(summary, 2) + "\n");
    outputs_[index] = {{"mapping", scene_.mappings[*o.mapping].name}, {"summary", summary}};
    addVerdict(outputs_[index], judgement);
  }

  void renderOutput(io::OutputSet& outputs, const SceneOutput& o, std::size_t index, MeshWork& work) {
    const MappedMesh& mapped = work.mapped.at(*o.mapping);
    const SceneMesh& sceneMesh = scene_.meshes[scene_.mappings[*o.mapping].mesh];
    const Mat4& model = sceneMesh.model;
    const FrameOptions& frame = o.frame.frame;
    const CameraSettings settings = o.camera ? scene_.cameras[*o.camera].settings : CameraSettings{};
    const render::Camera camera = settings.make(mapped.mesh, sceneMesh.path, model, frame.width, frame.height);
    const std::size_t texture = o.texture.value_or(scene_.textures.size());
    const analysis::Judgement* judged = nullptr;  // on the first call only
    const auto judgement = [&]() -> const analysis::Judgement& {
      if (!judged)
        judged = &judgementFor(work.judgements.at({*o.mapping, kViewsOverlapResolution}), mapped,
                               kViewsOverlapResolution, o.frame.densityTexture);
      return *judged;
    };
    json record = writeFrame(outputs, frame, o.path, o.frame.aovOutput, mapped,
                             renderOptions(frame, textureOf(scene_, texture).options(), textures_.at(texture), camera, model),
                             judgement);
    if (work.judgements.count({*o.mapping, kViewsOverlapResolution})) addVerdict(record, judgement());
    record["mapping"] = scene_.mappings[*o.mapping].name;
    record["mesh"] = scene_.meshes[scene_.mappings[*o.mapping].mesh].name;
    if (!o.json.empty()) outputs.writeText(o.json, io::jsonText(record, 2) + "\n");
    outputs_[index] = record;
  }

  json outputsJson() const {
    json out = json::array();
    for (std::size_t i = 0; i < scene_.outputs.size(); ++i) {
      static const char* kKinds[] = {"obj", "render", "report", "compare", "gallery", "bench"};
      json record = outputs_[i].is_null() ? json::object() : outputs_[i];
      record["kind"] = kKinds[int(scene_.outputs[i].kind)];
      record["files"] = scene_.outputs[i].files();
      out.push_back(record);
    }
    return out;
  }

  const Scene& scene_;
  const std::vector<Stage>& plan_;
  json records_;
  std::vector<json> outputs_;  // per output, written by the thread of its mesh
  std::vector<std::string> views3d_;
  std::deque<analysis::Judgement> ownJudgements_;  // judgementFor's, in a deque: references stay valid
  std::mutex ownJudgementsMutex_;  // per report output, its mapping's 3D view for the gallery (if any)
  std::map<std::size_t, BoundTexture> textures_;
  json failures_ = json::array();
  int status_ = 0;
  std::mutex mutex_;
  Progress* progress_ = nullptr;
  io::OutputSet staged_;  // the outputs of the stages that succeeded, until publishOutputs()
};

}  // namespace

const char* toString(Stage::Kind kind) {
  static const char* kNames[] = {"texture", "read",   "map",     "measure", "obj",
                                 "render",  "report", "compare", "gallery", "bench"};
  return kNames[int(kind)];
}

std::vector<Stage> planScene(const Scene& s) {
  const std::size_t defaultTexture = s.textures.size();
  std::vector<bool> mappingUsed(s.mappings.size()), meshUsed(s.meshes.size()), textureUsed(defaultTexture + 1);
  std::vector<std::set<int>> measures(s.mappings.size());
  const bool gallery = std::any_of(s.outputs.begin(), s.outputs.end(),
                                   [](const SceneOutput& o) { return o.kind == SceneOutput::Kind::Gallery; });
  // Whether an output reads the mapping's judgement: views of measures, OBJ summaries (as `uvtk map
  // --json`), and every picture a gallery labels with its verdict.
  const auto judged = [gallery](const SceneOutput& o) {
    return o.kind == SceneOutput::Kind::Mesh ||
           (o.kind == SceneOutput::Kind::Render && (gallery || o.frame.frame.showsMeasures()));
  };
  for (const SceneOutput& o : s.outputs) {
    if (o.kind == SceneOutput::Kind::Bench) continue;  // it reads its mesh itself
    if (o.mapping) mappingUsed[*o.mapping] = true, meshUsed[s.mappings[*o.mapping].mesh] = true;
    if (o.kind == SceneOutput::Kind::Compare) meshUsed[*o.mesh] = true;
    if (o.kind == SceneOutput::Kind::Render) textureUsed[o.texture.value_or(defaultTexture)] = true;
    if (judged(o)) measures[*o.mapping].insert(kViewsOverlapResolution);
    if (o.kind == SceneOutput::Kind::Report) measures[*o.mapping].insert(o.report.overlapResolution);
  }

  std::vector<Stage> plan;
  std::map<std::size_t, std::size_t> textureStage, mapStage;
  std::map<std::pair<std::size_t, int>, std::size_t> measureStage;
  for (std::size_t t = 0; t <= defaultTexture; ++t)
    if (textureUsed[t]) {
      textureStage[t] = plan.size();
      const TextureSettings& texture = textureOf(s, t);
      plan.push_back(
          {Stage::Kind::Texture,
           t,
           0,
           std::nullopt,
           (t < defaultTexture ? s.textures[t].name + ": " : "default: ") + texture.source,
           render::needsMipmaps(texture.filter) ? std::vector<std::string>{"mipmaps"} : std::vector<std::string>{},
           {}});
    }
  for (std::size_t m = 0; m < s.meshes.size(); ++m) {
    if (!meshUsed[m]) continue;
    const std::size_t read = plan.size();
    plan.push_back({Stage::Kind::Read, m, 0, m, s.meshes[m].name + ": " + s.meshes[m].path, {}, {}});
    for (std::size_t k = 0; k < s.mappings.size(); ++k) {
      const SceneMapping& mapping = s.mappings[k];
      if (mapping.mesh != m || !mappingUsed[k]) continue;
      std::vector<std::string> computes;
      if (mapping.needsNormals()) computes.push_back("vertex normals");
      if (mapping.seamPlaceAuto) computes.push_back("seam placement");
      mapStage[k] = plan.size();
      plan.push_back({Stage::Kind::Map, k, 0, m, mapping.name, computes, {read}});
    }
    for (std::size_t k = 0; k < s.mappings.size(); ++k)
      for (const int resolution : measures[k])
        if (s.mappings[k].mesh == m) {
          measureStage[{k, resolution}] = plan.size();
          plan.push_back({Stage::Kind::Measure,
                          k,
                          resolution,
                          m,
                          s.mappings[k].name,
                          {"distortion",
                           resolution == analysis::kOverlapFollowsMesh ? "overlap on a raster that follows the mesh"
                                                                       : "overlap on " + std::to_string(resolution) + "^2 pixels",
                           "verdict"},
                          {mapStage[k]}});
        }
    for (std::size_t i = 0; i < s.outputs.size(); ++i) {
      const SceneOutput& o = s.outputs[i];
      const std::optional<std::size_t> mesh = o.mapping ? std::optional(s.mappings[*o.mapping].mesh) : o.mesh;
      if (o.kind == SceneOutput::Kind::Gallery || o.kind == SceneOutput::Kind::Bench || mesh != m) continue;
      const std::vector<std::string> files = o.files();
      static const Stage::Kind kKinds[] = {Stage::Kind::Mesh, Stage::Kind::Render, Stage::Kind::Report,
                                           Stage::Kind::Compare};
      std::vector<std::string> computes;
      if (o.kind == SceneOutput::Kind::Render) computes = renderComputes(s, o);
      if (o.kind == SceneOutput::Kind::Report && !o.report.html.empty()) {
        std::string names;
        for (const views::View view : o.report.views) names += (names.empty() ? "" : ",") + std::string(views::toString(view));
        computes.push_back("views " + names);
      }
      if (o.kind == SceneOutput::Kind::Compare)
        computes.push_back(o.compare.baselines ? "every projector, LSCM and ARAP" : "every projector");
      std::vector<std::size_t> needs = {o.mapping ? mapStage[*o.mapping] : read};
      if (o.kind == SceneOutput::Kind::Render) needs.push_back(textureStage[o.texture.value_or(defaultTexture)]);
      if (judged(o)) needs.push_back(measureStage[{*o.mapping, kViewsOverlapResolution}]);
      if (o.kind == SceneOutput::Kind::Report) needs.push_back(measureStage[{*o.mapping, o.report.overlapResolution}]);
      plan.push_back({kKinds[int(o.kind)], i, 0, m, joined(files), computes, needs});
    }
  }
  for (std::size_t i = 0; i < s.outputs.size(); ++i) {
    const SceneOutput& o = s.outputs[i];
    if (o.kind != SceneOutput::Kind::Bench) continue;
    const std::size_t mesh = o.mapping ? s.mappings[*o.mapping].mesh : *o.mesh;
    plan.push_back({Stage::Kind::Bench, i, 0, mesh, joined(o.files()), benchComputes(o.bench), {}});
  }
  for (std::size_t i = 0; i < s.outputs.size(); ++i)
    if (s.outputs[i].kind == SceneOutput::Kind::Gallery)
      plan.push_back({Stage::Kind::Gallery, i, 0, std::nullopt, s.outputs[i].path, {}, {}});
  return plan;
}

json planJson(const Scene& scene, const std::vector<Stage>& plan) {
  json stages = json::array();
  for (const Stage& stage : plan) {
    json record = {{"stage", toString(stage.kind)}, {"subject", stage.subject}, {"computes", stage.computes}};
    if (stage.mesh) record["mesh"] = scene.meshes[*stage.mesh].name;
    stages.push_back(record);
  }
  return {{"scene", scene.path}, {"stages", stages}};
}

std::string planText(const Scene& scene, const std::vector<Stage>& plan) {
  std::string text = "uvtk run " + scene.path + ": " + std::to_string(plan.size()) + " stages\n";
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const Stage& stage = plan[i];
    char line[64];
    std::snprintf(line, sizeof line, "%3zu  %-8s ", i + 1, toString(stage.kind));
    text += line + stage.subject + (stage.computes.empty() ? "" : "  [" + joined(stage.computes) + "]") + "\n";
  }
  return text;
}

RunResult runScene(const Scene& scene, const std::vector<Stage>& plan, const RunOptions& options) {
  return SceneRunner(scene, plan).run(options);
}

}  // namespace uvtk::scene
