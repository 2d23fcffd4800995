// Emscripten 3.1.6's OpenAL (library_openal.js), completed for src/audio (cmake/web.cmake).
#include <AL/alext.h>

extern "C" {

// ALC_SOFT_loopback (AL/alext.h here): there is no loopback device, as alcIsExtensionPresent
// says; a caller that asks anyway gets none.
ALCdevice* alcLoopbackOpenDeviceSOFT(const ALCchar*) {
    return nullptr;
}

ALCboolean alcIsRenderFormatSupportedSOFT(ALCdevice*, ALCsizei, ALCenum, ALCenum) {
    return ALC_FALSE;
}

void alcRenderSamplesSOFT(ALCdevice*, ALCvoid*, ALCsizei) {}

// Emscripten's alSourceStopv hands source ids where its own code wants source objects
// ("Cannot read properties of undefined" in setSourceState); one alSourceStop each is the same.
void alSourceStopv(ALsizei count, const ALuint* sources) {
    for (ALsizei i = 0; i < count; ++i) alSourceStop(sources[i]);
}

}  // extern "C"
