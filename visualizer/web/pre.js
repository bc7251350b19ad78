// The page's address as the app's command line (web_main.cpp): #lesson=05&step=10 is
// --lesson 05 --step 10; a key without a value is a flag (#quiz). Values are URI-decoded.
// A page written by `stepwise lesson export --html` carries its lesson (stepwiseLesson, shell.html):
// its files go into the page's file system before main(), and it is the lesson opened unless the
// address names another. A new fragment opens what it names in the running page (sw_open), with
// no reload and the student's name kept; only one that needs a fresh page (another scale) reloads.
function stepwiseArguments(hash) {
  var args = [], named = {};
  hash.split("&").forEach(function (part) {
    if (!part) return;
    var eq = part.indexOf("=");
    var key = decodeURIComponent(eq < 0 ? part : part.substring(0, eq));
    named[key] = true;
    args.push("--" + key);
    if (eq >= 0) args.push(decodeURIComponent(part.substring(eq + 1)));
  });
  var own = typeof stepwiseLesson === "object" ? stepwiseLesson : null;
  if (own && !named.lesson && !named.algorithm) {
    args.unshift("--lesson", own.lesson);
    if (own.step !== null && !named.step) args.push("--step", String(own.step));
  }
  return args;
}

function stepwiseHash() {
  return (typeof location !== "undefined" && location.hash) ? location.hash.substring(1) : "";
}

Module["arguments"] = stepwiseArguments(stepwiseHash());

if (typeof stepwiseLesson === "object" && stepwiseLesson) {
  // Just before main(), after the page's own files are in place (a preRun of emcc's, which the
  // runtime runs after this one): a file of the same name (an edited lesson of the page) replaces one.
  Module["preRun"] = (Module["preRun"] || []).concat([function () {
    addOnPreMain(function () {
      stepwiseLesson.files.forEach(function (f) {
        FS.mkdirTree(f.path.substring(0, f.path.lastIndexOf("/")));
        FS.writeFile(f.path, f.text);
      });
    });
  }]);
}

if (typeof window !== "undefined") {
  window.addEventListener("hashchange", function () {
    var args = JSON.stringify(stepwiseArguments(stepwiseHash()));
    if (!runtimeInitialized || Module.ccall("sw_open", "number", ["string"], [args]) !== 0) location.reload();
  });
}
