// The interactive API reference at /docs: swagger-ui from static/vendor (scripts/assets.sh), our own spec.
// A file, not an inline script, so the Content-Security-Policy can allow scripts from this origin only.
const root = document.getElementById("swagger-ui");
window.SwaggerUIBundle({
  url: root.dataset.spec,
  domNode: root,
  deepLinking: true,
  validatorUrl: null, // the default sends the spec to an outside validator
});
