// The web build's <AL/alext.h> (cmake/web.cmake). Emscripten's OpenAL (on Web Audio) ships no
// alext.h and has no ALC_SOFT_loopback, which src/audio uses only to render sound offline for
// its tests, after asking alcIsExtensionPresent (false here). The names it compiles against are
// OpenAL Soft's (their values from its alext.h); openal_web.cpp answers the functions.
#pragma once
#include <AL/al.h>
#include <AL/alc.h>

#define ALC_FORMAT_CHANNELS_SOFT 0x1990
#define ALC_FORMAT_TYPE_SOFT 0x1991
#define ALC_FLOAT_SOFT 0x1406
#define ALC_STEREO_SOFT 0x1501
#define ALC_HRTF_SOFT 0x1992

#ifdef __cplusplus
extern "C" {
#endif
ALCdevice* alcLoopbackOpenDeviceSOFT(const ALCchar* device_name);
ALCboolean alcIsRenderFormatSupportedSOFT(ALCdevice* device, ALCsizei freq, ALCenum channels,
                                          ALCenum type);
void alcRenderSamplesSOFT(ALCdevice* device, ALCvoid* buffer, ALCsizei samples);
#ifdef __cplusplus
}
#endif
