// The lab draws its first frame before the η table has arrived
// (the scene at t = 0, seek steering). This badge over the canvas says so
// until the table is in force and the clock runs; it fades out then.

/** The badge's handle: `done` when the table is in, `fail` when none came. */
export interface TableBadge {
  done(): void;
  fail(text: string): void;
}

/** Puts the "loading η table…" badge in `stage` (the canvas's container). */
export function tableBadge(stage: HTMLElement): TableBadge {
  const el = document.createElement("div");
  el.className = "table-badge";
  el.setAttribute("role", "status");
  el.textContent = "loading η table…";
  const detail = document.createElement("span");
  detail.className = "detail";
  detail.textContent = " (seek view, t = 0)";
  el.append(detail);
  stage.append(el);
  return {
    done() {
      el.classList.add("gone");
      el.textContent = "η table loaded: funnelling";
      setTimeout(() => el.remove(), 700);
    },
    fail(text: string) {
      el.classList.add("failed");
      el.textContent = text;
    },
  };
}
