/* scene_mark.c — taking out what was added to a scene after a mark (scene_mark.h). */
#include "scene/scene_mark.h"

#include <stdlib.h>

scene_mark scene_mark_take(const scene *s)
{
    return (scene_mark){.materials = s->n_materials, .textures = s->n_textures, .species = s->n_species,
                        .prototypes = s->n_prototypes, .instances = s->n_instances, .objects = s->n_objects,
                        .models = s->n_models};
}

/* The material names index rebuilt over the materials left (it borrows their names). */
static int index_materials(scene *s, err_buf *err)
{
    name_index_free(&s->material_names);
    for (uint32_t i = 0; i < s->n_materials; i++)
        if (name_index_add(&s->material_names, s->materials[i].name, i) < 0)
            return err_nomem(err, "out of memory indexing the scene's materials");
    return 0;
}

int scene_rewind(scene *s, const scene_mark *m, err_buf *err)
{
    for (uint32_t i = m->prototypes; i < s->n_prototypes; i++) mesh_free(s->prototypes[i].mesh);
    for (uint32_t i = m->species; i < s->n_species; i++) free(s->species[i].name);
    for (uint32_t i = m->textures; i < s->n_textures; i++) free(s->textures[i].name), free(s->textures[i].rgba);
    for (uint32_t i = m->objects; i < s->n_objects; i++) free(s->objects[i].name), mesh_free(s->objects[i].mesh);
    for (uint32_t i = m->models; i < s->n_models; i++) free(s->models[i].name), mesh_free(s->models[i].mesh);
    int renamed = s->n_materials > m->materials;
    for (uint32_t i = m->materials; i < s->n_materials; i++) free(s->materials[i].name);
    s->n_prototypes = m->prototypes, s->n_species = m->species, s->n_textures = m->textures;
    s->n_objects = m->objects, s->n_models = m->models, s->n_instances = m->instances;
    s->n_materials = m->materials;
    return renamed ? index_materials(s, err) : 0;
}
