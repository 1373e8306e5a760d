/**
 * A lit-html element directive that keeps one long-lived object (a 3D view with its WebGL context) per host
 * element across re-renders. The panel re-renders whole views often; a new WebGL context each time would be
 * slow and would soon hit the browser's limit, so the object is kept in a WeakMap keyed by the element, given
 * the new options on every render, and disposed when lit removes the element (the directive is disconnected).
 *
 *     const view = mountDirective((host) => new RobotCanvas(host));
 *     html`<div ${view(options)}></div>`
 */
import { nothing } from "lit-html";
import { AsyncDirective } from "lit-html/async-directive.js";
import { directive, type ElementPart, type PartInfo, PartType } from "lit-html/directive.js";

export interface Mounted<O> {
  setOptions(options: O): void;
  dispose(): void;
}

export function mountDirective<O>(create: (host: HTMLElement) => Mounted<O>) {
  const mounted = new WeakMap<Element, Mounted<O>>();

  class MountDirective extends AsyncDirective {
    private host: HTMLElement | undefined;
    private options: O | undefined;

    constructor(part: PartInfo) {
      super(part);
      if (part.type !== PartType.ELEMENT)
        throw new Error("a mount directive goes on an element, as an attribute-position expression");
    }

    render(_options: O): typeof nothing {
      return nothing;
    }

    override update(part: ElementPart, [options]: [O]): typeof nothing {
      const host = part.element;
      if (!(host instanceof HTMLElement)) return nothing;
      if (this.host && this.host !== host) this.release();
      this.host = host;
      this.options = options;
      if (this.isConnected) this.mount(host).setOptions(options);
      return nothing;
    }

    protected override disconnected(): void {
      this.release();
    }

    protected override reconnected(): void {
      if (this.host && this.options !== undefined) this.mount(this.host).setOptions(this.options);
    }

    private mount(host: HTMLElement): Mounted<O> {
      let m = mounted.get(host);
      if (!m) {
        m = create(host);
        mounted.set(host, m);
      }
      return m;
    }

    private release(): void {
      if (!this.host) return;
      mounted.get(this.host)?.dispose();
      mounted.delete(this.host);
    }
  }

  return directive(MountDirective);
}
