// assimp_shim.cpp — the model module (sylva_model.so, model/model_module.h): a model file read by
// Assimp's importer, loaded by the core on first use (model/model_assimp.c). Only the readers of
// the file's extension may read it: Assimp would otherwise hand a file its own reader refuses to
// every other reader in turn (a damaged glTF file read as an OBJ, say). The file is read once
// with its data structure validated; a face of no vertices is refused there, before
// Assimp's triangulation (which aborts the program on one) runs on the same scene. The importer
// owns the scene and frees it when a step fails, so a failed step never frees it twice. Every
// operation catches whatever Assimp or the standard library throws.
#include "model/model_module.h"

#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cctype>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <set>
#include <string>

struct model_reading {
    Assimp::Importer importer;
};

namespace {

// A file the core's aiFileIO opened, as Assimp's C++ interface reads it; it is in its file
// system's set of open files while it lives (Assimp closes some with Close, deletes others).
class core_stream : public Assimp::IOStream {
public:
    core_stream(aiFileIO *io, aiFile *file, std::set<core_stream *> *open) : io_(io), file_(file), open_(open) {}
    ~core_stream() override
    {
        open_->erase(this);
        io_->CloseProc(io_, file_);
    }
    size_t Read(void *buffer, size_t size, size_t count) override
    {
        return file_->ReadProc(file_, static_cast<char *>(buffer), size, count);
    }
    size_t Write(const void *, size_t, size_t) override { return 0; } // models are only read
    aiReturn Seek(size_t offset, aiOrigin origin) override { return file_->SeekProc(file_, offset, origin); }
    size_t Tell() const override { return file_->TellProc(file_); }
    size_t FileSize() const override { return file_->FileSizeProc(file_); }
    void Flush() override {}

private:
    aiFileIO *io_;
    aiFile *file_;
    std::set<core_stream *> *open_;
};

// The core's aiFileIO (the model's folder, model/model_folder.h) as Assimp's file system. A file
// exists when it opens, as in Assimp's C interface. Assimp's readers leave a file open when they
// throw between opening and closing it (an OBJ's material library that cannot be read, say): the
// files still open are closed with the file system, which the importer owns.
class core_files : public Assimp::IOSystem {
public:
    explicit core_files(const aiFileIO *io) : io_(*io) {}
    ~core_files() override
    {
        while (!open_.empty()) delete *open_.begin(); // each leaves the set as it goes
    }
    bool Exists(const char *path) const override
    {
        aiFile *f = io_.OpenProc(&io_, path, "rb");
        if (f) io_.CloseProc(&io_, f);
        return f != nullptr;
    }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream *Open(const char *path, const char *mode) override
    {
        aiFile *f = io_.OpenProc(&io_, path, mode);
        if (!f) return nullptr;
        core_stream *s = new (std::nothrow) core_stream(&io_, f, &open_); // deleted by Assimp or ~core_files
        if (!s) {
            io_.CloseProc(&io_, f);
            return nullptr;
        }
        try {
            open_.insert(s);
        } catch (...) {
            delete s;
            return nullptr;
        }
        return s;
    }
    void Close(Assimp::IOStream *s) override { delete s; }

private:
    mutable aiFileIO io_;           // the C callbacks take it by non-const pointer
    std::set<core_stream *> open_; // the files opened and not yet closed
};

// The first face of no vertices in scene, as "mesh M, face F" into why; false when there is none.
bool empty_face(const aiScene *scene, char *why, size_t n)
{
    for (unsigned m = 0; m < scene->mNumMeshes; m++)
        for (unsigned f = 0; scene->mMeshes[m] && f < scene->mMeshes[m]->mNumFaces; f++)
            if (!scene->mMeshes[m]->mFaces[f].mNumIndices) {
                std::snprintf(why, n, "mesh %u, face %u", m, f);
                return true;
            }
    return false;
}

// Leaves in importer only the readers of path's extension (in any case).
void keep_readers_of(Assimp::Importer &importer, const char *path)
{
    const char *dot = std::strrchr(path, '.'), *slash = std::strrchr(path, '/');
    std::string ext = dot && (!slash || dot > slash) ? dot + 1 : "";
    for (char &c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (size_t i = importer.GetImporterCount(); i-- > 0;) {
        Assimp::BaseImporter *reader = importer.GetImporter(i);
        std::set<std::string> extensions;
        reader->GetExtensionList(extensions);
        if (extensions.count(ext)) continue;
        importer.UnregisterLoader(reader);
        delete reader; // no longer the importer's
    }
}

model_read_status failed(model_reading *r, char *why, size_t n)
{
    std::snprintf(why, n, "%s", r->importer.GetErrorString());
    return MODEL_READ_FAILED;
}

model_read_status read(const char *path, const aiFileIO *io, model_reading **out, const aiScene **scene, char *why,
                       size_t n)
{
    *out = nullptr, *scene = nullptr;
    if (n) why[0] = '\0';
    try {
        model_reading *r = new model_reading; // the caller's: closed by close
        *out = r;
        r->importer.SetIOHandler(new core_files(io)); // the importer's from here
        keep_readers_of(r->importer, path);
        r->importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
        if (!r->importer.ReadFile(path, aiProcess_ValidateDataStructure)) return failed(r, why, n);
        if (empty_face(r->importer.GetScene(), why, n)) return MODEL_READ_EMPTY_FACE;
        const aiScene *done = r->importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType);
        if (!done) return failed(r, why, n);
        *scene = done;
        return MODEL_READ_OK;
    } catch (const std::bad_alloc &) {
        return MODEL_READ_NOMEM;
    } catch (const std::exception &e) {
        std::snprintf(why, n, "%s", e.what());
        return MODEL_READ_FAILED;
    } catch (...) {
        std::snprintf(why, n, "the model reader stopped without a reason");
        return MODEL_READ_FAILED;
    }
}

void close(model_reading *r)
{
    delete r; // the importer frees its scene and its file system
}

aiReturn material_color(const aiMaterial *m, const char *key, unsigned type, unsigned index, aiColor4D *out)
{
    return aiGetMaterialColor(m, key, type, index, out);
}

aiReturn material_string(const aiMaterial *m, const char *key, unsigned type, unsigned index, aiString *out)
{
    return aiGetMaterialString(m, key, type, index, out);
}

aiReturn material_floats(const aiMaterial *m, const char *key, unsigned type, unsigned index, float *out,
                         unsigned *count)
{
    return aiGetMaterialFloatArray(m, key, type, index, out, count);
}

aiReturn material_texture(const aiMaterial *m, aiTextureType type, unsigned index, aiString *path)
{
    return aiGetMaterialTexture(m, type, index, path, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr);
}

const model_module table = {sizeof(model_module), MODEL_MODULE_VERSION, read, close,
                            material_color, material_string, material_floats, material_texture};

} // namespace

extern "C" __attribute__((visibility("default"))) const model_module *sylva_model_module(void)
{
    return &table;
}
