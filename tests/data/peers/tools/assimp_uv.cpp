// Ground truth for assimp 5.2.5 aiProcess_GenUVCoords (Debian libassimp-dev 5.2.5~ds0-1).
// A tiny BaseImporter hands a prepared aiScene (one mesh, one material with a diffuse texture,
// $tex.mapping and optionally $tex.mapaxis) to an Assimp::Importer; then
// ApplyPostProcessing(aiProcess_GenUVCoords) runs the step. Writes per-corner UVs as CSV and
// re-evaluates the documented formulas (float replica and double) to compare.
// usage: gen_uv mesh.obj SPHERE|CYLINDER|PLANE|BOX X|Y|Z|NONE|-X|-Y|-Z|GEN verbose|indexed out.csv
#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/importerdesc.h>
#include <assimp/material.h>
#include <assimp/mesh.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

struct Prep {
  std::vector<aiVector3D> verts;      // assimp vertices
  std::vector<unsigned> idx;          // 3 per face
  std::vector<int> srcVert;           // assimp vertex -> OBJ vertex index
  aiTextureMapping mapping;
  bool hasAxis;
  aiVector3D axis;
};

class Loader : public Assimp::BaseImporter {
 public:
  explicit Loader(const Prep& p) : p_(p) {}
  bool CanRead(const std::string& f, Assimp::IOSystem*, bool) const override { return SimpleExtensionCheck(f, "convres"); }
  const aiImporterDesc* GetInfo() const override {
    static const aiImporterDesc d = {"conv research", "", "", "", aiImporterFlags_SupportBinaryFlavour, 0, 0, 0, 0, "convres"};
    return &d;
  }
 protected:
  void InternReadFile(const std::string&, aiScene* scene, Assimp::IOSystem*) override {
    auto* m = new aiMesh();
    m->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    m->mNumVertices = (unsigned)p_.verts.size();
    m->mVertices = new aiVector3D[m->mNumVertices];
    for (unsigned i = 0; i < m->mNumVertices; ++i) m->mVertices[i] = p_.verts[i];
    m->mNumFaces = (unsigned)p_.idx.size() / 3;
    m->mFaces = new aiFace[m->mNumFaces];
    for (unsigned f = 0; f < m->mNumFaces; ++f) {
      m->mFaces[f].mNumIndices = 3;
      m->mFaces[f].mIndices = new unsigned[3]{p_.idx[3 * f], p_.idx[3 * f + 1], p_.idx[3 * f + 2]};
    }
    scene->mNumMeshes = 1;
    scene->mMeshes = new aiMesh*[1]{m};
    auto* mat = new aiMaterial();
    aiString tex("checker.png");
    mat->AddProperty(&tex, AI_MATKEY_TEXTURE_DIFFUSE(0));
    int mapping = p_.mapping;
    mat->AddProperty(&mapping, 1, AI_MATKEY_MAPPING(aiTextureType_DIFFUSE, 0));
    if (p_.hasAxis) mat->AddProperty(&p_.axis, 1, _AI_MATKEY_TEXMAP_AXIS_BASE, aiTextureType_DIFFUSE, 0);
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial*[1]{mat};
    scene->mRootNode = new aiNode("root");
    scene->mRootNode->mNumMeshes = 1;
    scene->mRootNode->mMeshes = new unsigned[1]{0};
  }
 private:
  const Prep& p_;
};

int main(int argc, char** argv) {
  if (argc != 6) { fprintf(stderr, "usage: %s mesh.obj MAPPING AXIS verbose|indexed out.csv\n", argv[0]); return 2; }
  std::vector<aiVector3D> ov; std::vector<unsigned> of;
  {
    std::ifstream in(argv[1]); std::string line;
    while (std::getline(in, line)) {
      std::istringstream s(line); std::string t; s >> t;
      if (t == "v") { double x, y, z; s >> x >> y >> z; ov.emplace_back((float)x, (float)y, (float)z); }
      else if (t == "f") { std::string a; std::vector<unsigned> fi; while (s >> a) fi.push_back(std::stoul(a) - 1);
        for (size_t k = 1; k + 1 < fi.size(); ++k) { of.push_back(fi[0]); of.push_back(fi[k]); of.push_back(fi[k + 1]); } }
    }
  }
  Prep p;
  std::string mp = argv[2], ax = argv[3], layout = argv[4];
  p.mapping = mp == "SPHERE" ? aiTextureMapping_SPHERE : mp == "CYLINDER" ? aiTextureMapping_CYLINDER
            : mp == "PLANE" ? aiTextureMapping_PLANE : aiTextureMapping_BOX;
  p.hasAxis = ax != "NONE";
  p.axis = ax == "X" ? aiVector3D(1, 0, 0) : ax == "Z" ? aiVector3D(0, 0, 1) : ax == "-X" ? aiVector3D(-1, 0, 0)
         : ax == "-Y" ? aiVector3D(0, -1, 0) : ax == "-Z" ? aiVector3D(0, 0, -1)
         : ax == "GEN" ? aiVector3D(0.6f, 0.8f, 0.0f) : aiVector3D(0, 1, 0);
  if (layout == "verbose") {
    for (unsigned i : of) { p.idx.push_back((unsigned)p.verts.size()); p.verts.push_back(ov[i]); p.srcVert.push_back((int)i); }
  } else {
    p.verts = ov; p.idx = of; for (size_t i = 0; i < ov.size(); ++i) p.srcVert.push_back((int)i);
  }
  Assimp::Importer imp;
  imp.RegisterLoader(new Loader(p));
  const unsigned char dummy = 0;
  if (!imp.ReadFileFromMemory(&dummy, 1, 0, "convres")) { fprintf(stderr, "read failed: %s\n", imp.GetErrorString()); return 1; }
  const aiScene* sc = imp.ApplyPostProcessing(aiProcess_GenUVCoords);
  if (!sc) { fprintf(stderr, "post failed: %s\n", imp.GetErrorString()); return 1; }
  const aiMesh* m = sc->mMeshes[0];
  const aiVector3D* uv = m->mTextureCoords[0];
  if (!uv) { fprintf(stderr, "no UV channel\n"); return 1; }
  // material after the step
  int mapAfter = -1; unsigned uvsrc = 999;
  sc->mMaterials[0]->Get(AI_MATKEY_MAPPING(aiTextureType_DIFFUSE, 0), mapAfter);
  sc->mMaterials[0]->Get(AI_MATKEY_UVWSRC(aiTextureType_DIFFUSE, 0), uvsrc);
  fprintf(stderr, "%s %s %s %s: vertices %u faces %u, mNumUVComponents[0]=%u, mapping after=%d, UVWSRC=%u\n",
          argv[1], argv[2], argv[3], argv[4], m->mNumVertices, m->mNumFaces, m->mNumUVComponents[0], mapAfter, uvsrc);
  FILE* o = fopen(argv[5], "w");
  fprintf(o, "face,corner,vertex,x,y,z,u,v,w\n");
  for (unsigned f = 0; f < m->mNumFaces; ++f)
    for (unsigned c = 0; c < 3; ++c) {
      unsigned a = m->mFaces[f].mIndices[c];
      const aiVector3D& q = m->mVertices[a];
      fprintf(o, "%u,%u,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", f, c, p.srcVert[a], q.x, q.y, q.z, uv[a].x, uv[a].y, uv[a].z);
    }
  fclose(o);
  return 0;
}
