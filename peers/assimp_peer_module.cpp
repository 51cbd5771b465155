// assimp's aiProcess_GenUVCoords timed on a uvtk mesh: the plugin libuvtk_peer_assimp.so, which
// assimp_peer.cpp opens when `uvtk bench` times the peer (assimp and what it links, draco, minizip
// and brotli, cost 4.5 ms of every process's start when linked in). See assimp_peer.h and README.md.
//
// How the step is reached: assimp's post-processing steps are internal classes, reachable only
// through an Assimp::Importer that owns a scene. An Importer only owns scenes one of its loaders
// produced, so this file registers a tiny loader (a BaseImporter for the made-up extension
// "uvtkpeer") whose "file" is the scene prepared here. Per repetition, untimed:
// ReadFileFromMemory(dummy byte, no post-processing flags, hint "uvtkpeer") gives the importer a
// fresh copy of the scene; timed: ApplyPostProcessing(aiProcess_GenUVCoords). A fresh copy each
// time is needed because the step rewrites the material's mapping to UV after it ran.
#include "peers/assimp_peer_module.h"

#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/importerdesc.h>
#include <assimp/material.h>
#include <assimp/mesh.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <string>

namespace uvtk::peers {
namespace {

constexpr const char* kExtension = "uvtkpeer";

aiTextureMapping toAssimp(AssimpMapping mapping) {
  switch (mapping) {
    case AssimpMapping::Sphere: return aiTextureMapping_SPHERE;
    case AssimpMapping::Cylinder: return aiTextureMapping_CYLINDER;
    case AssimpMapping::Plane: return aiTextureMapping_PLANE;
    case AssimpMapping::Box: return aiTextureMapping_BOX;
  }
  return aiTextureMapping_SPHERE;
}

// The prepared scene contents, copied into a new aiScene on every "import".
struct PreparedScene {
  std::vector<aiVector3D> vertices;
  std::vector<unsigned int> indices;  // 3 per face
  aiTextureMapping mapping = aiTextureMapping_SPHERE;
};

class PeerSceneLoader : public Assimp::BaseImporter {
 public:
  explicit PeerSceneLoader(const PreparedScene& prepared) : prepared_(prepared) {}

  bool CanRead(const std::string& file, Assimp::IOSystem*, bool) const override {
    return SimpleExtensionCheck(file, kExtension);
  }

  const aiImporterDesc* GetInfo() const override {
    static const aiImporterDesc desc = {
        "uvtk peer scene", "uvtk", "uvtk", "in-memory scene for timing post-processing steps",
        aiImporterFlags_SupportBinaryFlavour, 0, 0, 0, 0, kExtension};
    return &desc;
  }

 protected:
  // Runs inside Importer::ReadFile, outside the timed region. The aiScene's destructor frees
  // everything allocated here, hence the new[].
  void InternReadFile(const std::string&, aiScene* scene, Assimp::IOSystem*) override {
    auto* mesh = new aiMesh();
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mMaterialIndex = 0;
    mesh->mNumVertices = static_cast<unsigned int>(prepared_.vertices.size());
    mesh->mVertices = new aiVector3D[mesh->mNumVertices];
    std::copy(prepared_.vertices.begin(), prepared_.vertices.end(), mesh->mVertices);
    mesh->mNumFaces = static_cast<unsigned int>(prepared_.indices.size() / 3);
    mesh->mFaces = new aiFace[mesh->mNumFaces];
    for (unsigned int f = 0; f < mesh->mNumFaces; ++f) {
      aiFace& face = mesh->mFaces[f];
      face.mNumIndices = 3;
      face.mIndices = new unsigned int[3];
      std::memcpy(face.mIndices, &prepared_.indices[3 * std::size_t(f)], 3 * sizeof(unsigned int));
    }
    scene->mNumMeshes = 1;
    scene->mMeshes = new aiMesh*[1]{mesh};

    auto* material = new aiMaterial();
    const aiString name(std::string("uvtk_peer"));
    material->AddProperty(&name, AI_MATKEY_NAME);
    const aiString texture(std::string("checker.png"));
    material->AddProperty(&texture, AI_MATKEY_TEXTURE_DIFFUSE(0));
    const int mapping = prepared_.mapping;
    material->AddProperty(&mapping, 1, AI_MATKEY_MAPPING(aiTextureType_DIFFUSE, 0));
    const aiVector3D axis(0, 1, 0);  // assimp's default axis, stated explicitly
    material->AddProperty(&axis, 1, _AI_MATKEY_TEXMAP_AXIS_BASE, aiTextureType_DIFFUSE, 0);
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial*[1]{material};

    scene->mRootNode = new aiNode("uvtk_peer");
    scene->mRootNode->mNumMeshes = 1;
    scene->mRootNode->mMeshes = new unsigned int[1]{0};
  }

 private:
  const PreparedScene& prepared_;
};

std::optional<PeerTiming> measure(const Mesh& mesh, AssimpMapping mapping, int repetitions, AssimpLayout layout) {
  const std::size_t n = mesh.positions.size();
  if (n == 0 || mesh.triangles.empty()) return std::nullopt;
  for (const Triangle& t : mesh.triangles)
    for (int i : t)
      if (i < 0 || std::size_t(i) >= n) return std::nullopt;
  repetitions = std::max(repetitions, 1);

  PreparedScene prepared;
  prepared.mapping = toAssimp(mapping);
  const auto toAi = [](const Vec3& p) {
    return aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()),
                      static_cast<ai_real>(p.z()));
  };
  prepared.indices.reserve(3 * mesh.triangles.size());
  if (layout == AssimpLayout::Verbose) {
    prepared.vertices.reserve(3 * mesh.triangles.size());
    for (const Triangle& t : mesh.triangles)
      for (int i : t) {
        prepared.indices.push_back(static_cast<unsigned int>(prepared.vertices.size()));
        prepared.vertices.push_back(toAi(mesh.positions[std::size_t(i)]));
      }
  } else {
    prepared.vertices.reserve(n);
    for (const Vec3& p : mesh.positions) prepared.vertices.push_back(toAi(p));
    for (const Triangle& t : mesh.triangles)
      for (int i : t) prepared.indices.push_back(static_cast<unsigned int>(i));
  }

  Assimp::Importer importer;
  if (!importer.ValidateFlags(aiProcess_GenUVCoords)) return std::nullopt;
  // The importer takes ownership of the loader and deletes it with itself.
  if (importer.RegisterLoader(new PeerSceneLoader(prepared)) != aiReturn_SUCCESS) return std::nullopt;

  const unsigned char dummy = 0;  // ReadFileFromMemory insists on a non-empty buffer
  std::vector<double> times;
  times.reserve(std::size_t(repetitions));
  const aiScene* scene = nullptr;
  for (int r = -1; r < repetitions; ++r) {  // r = -1: untimed warm-up run
    if (!importer.ReadFileFromMemory(&dummy, 1, 0, kExtension)) return std::nullopt;
    const auto start = std::chrono::steady_clock::now();
    scene = importer.ApplyPostProcessing(aiProcess_GenUVCoords);
    const auto stop = std::chrono::steady_clock::now();
    if (!scene) return std::nullopt;
    if (r >= 0) times.push_back(std::chrono::duration<double, std::nano>(stop - start).count());
  }

  const aiMesh* out = scene->mNumMeshes == 1 ? scene->mMeshes[0] : nullptr;
  if (!out || !out->mTextureCoords[0]) return std::nullopt;

  std::sort(times.begin(), times.end());
  const std::size_t m = times.size();
  const double median = m % 2 ? times[m / 2] : 0.5 * (times[m / 2 - 1] + times[m / 2]);

  PeerTiming timing;
  timing.vertices = out->mNumVertices;
  timing.medianNs = median;
  timing.nsPerVertex = median / double(timing.vertices);
  timing.nsPerMeshVertex = median / double(n);
  timing.repetitions = repetitions;
  timing.uv.resize(timing.vertices);
  for (unsigned int i = 0; i < out->mNumVertices; ++i)
    timing.uv[i] = Eigen::Vector2d(out->mTextureCoords[0][i].x, out->mTextureCoords[0][i].y);
  return timing;
}

bool measureInto(const Mesh& mesh, AssimpMapping mapping, int repetitions, AssimpLayout layout, PeerTiming& out) {
  std::optional<PeerTiming> timing = measure(mesh, mapping, repetitions, layout);
  if (!timing) return false;
  out = std::move(*timing);
  return true;
}

constexpr AssimpPeerFunctions kFunctions{kAssimpPeerVersion, measureInto};

}  // namespace

}  // namespace uvtk::peers

extern "C" __attribute__((visibility("default"))) const uvtk::peers::AssimpPeerFunctions* uvtk_assimp_peer() {
  return &uvtk::peers::kFunctions;
}
