/**
 * A part of a view that is not in the first page load: `get` gives the module once it has loaded; before that it
 * starts loading it (once) and gives undefined, so the view draws a stand-in; when the module arrives, `loaded`
 * is called to draw again. A failed load is tried again on the next `get`.
 */
export function lazyPart<M>(load: () => Promise<M>): { get(loaded: () => void): M | undefined } {
  let module: M | undefined;
  let loading = false;
  return {
    get(loaded) {
      if (module) return module;
      if (!loading) {
        loading = true;
        load().then(
          (m) => {
            module = m;
            loaded();
          },
          () => {
            loading = false;
          },
        );
      }
      return undefined;
    },
  };
}
