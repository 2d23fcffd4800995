// The game's files in the browser (linked with --pre-js): the settings and the saved game live
// under $HOME (/home/web_user), an IndexedDB file system read before main() starts and written
// back after each change (platform_web.cpp calls Module.coolaaberStoreFiles).
Module['preRun'] = Module['preRun'] || [];
Module['preRun'].push(function () {
  FS.mount(IDBFS, {}, '/home/web_user');
  addRunDependency('coolaaber-files');
  FS.syncfs(true, function (err) {
    if (err) console.warn('The saved game and settings could not be read from the browser: ' + err);
    removeRunDependency('coolaaber-files');
  });
});

var coolaaberStoring = false, coolaaberStoreAgain = false;
Module['coolaaberStoreFiles'] = function () {
  if (coolaaberStoring) { coolaaberStoreAgain = true; return; }  // one sync at a time
  coolaaberStoring = true;
  FS.syncfs(false, function (err) {
    coolaaberStoring = false;
    if (err) console.warn('The saved game and settings could not be stored in the browser: ' + err);
    if (coolaaberStoreAgain) { coolaaberStoreAgain = false; Module['coolaaberStoreFiles'](); }
  });
};
