// Kinolab's script worker: runs a learner's code off the page's thread,
// in a WebAssembly instance of its own. The page hands over the module it
// has compiled (nothing is downloaded twice) and the address of its
// JavaScript glue. A run that crashes ends this worker, never the page.
let lab = null;

self.onmessage = async (event) => {
  const { glue, module, job } = event.data;
  try {
    if (lab === null) {
      lab = await import(glue);
      lab.initSync({ module });
    }
    self.postMessage({ answer: lab.kinolab_script_job(job) });
  } catch (error) {
    self.postMessage({ crashed: String((error && error.message) || error) });
  }
};
