/* A plugin that goes wrong in one way, chosen when it is built (MISBEHAVE_...), for the tests of the loader
 * and the host: each way must end in a clear error naming the library, never in rast's own crash. Where
 * it behaves, it draws nothing. */
#include <rast/plugin.h>

#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#ifdef MISBEHAVE_CRASH_ON_LOAD
__attribute__((constructor)) static void crash_on_load(void) { raise(SIGSEGV); }
#endif

int rast_plugin_abi_version(void) {
#ifdef MISBEHAVE_WRONG_VERSION
    return 2;
#else
    return RAST_PLUGIN_ABI_VERSION;
#endif
}

const char *rast_plugin_contract(void) {
#if defined(MISBEHAVE_NULL_CONTRACT)
    return NULL;
#elif defined(MISBEHAVE_UNKNOWN_KEY)
    return "name=bad samples=1 snap=none ties=top-left depth=zid colour=red";
#elif defined(MISBEHAVE_BAD_VALUE)
    return "name=bad samples=1 snap=8 rounding=sideways ties=top-left depth=zid";
#else
    return "name=misbehaving samples=1,4 snap=none ties=top-left depth=zid";
#endif
}

#ifndef MISBEHAVE_NO_RENDER
int rast_plugin_render(const rast_plugin_scene *scene, int32_t *ids, char *err, size_t errlen) {
    const size_t count = (size_t)scene->width * (size_t)scene->height * (size_t)scene->samples;
    for (size_t k = 0; k < count; ++k) ids[k] = -1;
#if defined(MISBEHAVE_RENDER_ERROR)
    snprintf(err, errlen, "the scene has %llu triangles and I draw none", (unsigned long long)scene->triangle_count);
    return 3;
#elif defined(MISBEHAVE_CRASH)
    if (scene->triangle_count > 0) raise(SIGSEGV);
#elif defined(MISBEHAVE_EXIT)
    _exit(127); /* the status a failed exec gives: here it is the plugin's own */
#elif defined(MISBEHAVE_CLOSE_AND_HANG)
    close(3); /* the host's socket, as a plugin that closes every descriptor might */
    for (;;) pause();
#elif defined(MISBEHAVE_HANG)
    for (;;) pause();
#elif defined(MISBEHAVE_ID_OUT_OF_RANGE)
    ids[count - 1] = (int32_t)scene->triangle_count;
#elif defined(MISBEHAVE_PRINTS)
    printf("a plugin that talks on stdout\n");
    fflush(stdout);
#endif
    (void)err;
    (void)errlen;
    return 0;
}
#endif
