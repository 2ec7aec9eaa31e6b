import { createLab, StateField as F, Mode } from "steering-core";

const lab = await createLab(); // the wasm module and the package's η table
const goal = { x: 5, y: 2, beta: Math.PI / 2, dTol: 0.25, epsTol: (5 * Math.PI) / 180, speed: 1.3, halting: true, relaxed: false };
lab.addAgent({ x: -5, y: -2, theta: 0, goals: [goal] }); // radians and metres
const canvas = document.getElementById("view"), ctx = canvas.getContext("2d"), status = document.getElementById("status");
const view = () => ({ k: Math.min(canvas.width, canvas.height) / 16, cx: canvas.width / 2, cy: canvas.height / 2 }); // 16 m across
const toWorld = (e) => { const { k, cx, cy } = view(), r = devicePixelRatio; return { x: (e.offsetX * r - cx) / k, y: (cy - e.offsetY * r) / k }; };
const tip = () => ({ x: goal.x + Math.cos(goal.beta), y: goal.y + Math.sin(goal.beta) }); // the handle that turns the target
const near = (p, q, px) => (Math.hypot(p.x - q.x, p.y - q.y) * view().k) / devicePixelRatio < px; // within px CSS pixels: a finger's reach
const trail = [];
let drag = null;
canvas.addEventListener("pointerdown", (e) => {
  const p = toWorld(e);
  drag = near(p, tip(), 24) ? "turn" : near(p, goal, 32) ? "move" : null;
  if (drag) canvas.setPointerCapture(e.pointerId);
});
canvas.addEventListener("pointermove", (e) => {
  if (!drag) return;
  const p = toWorld(e);
  if (drag === "move") Object.assign(goal, p); else goal.beta = Math.atan2(p.y - goal.y, p.x - goal.x);
  lab.setGoal(0, goal); // the agent's queue restarts towards the moved target
});
for (const type of ["pointerup", "pointercancel"]) canvas.addEventListener(type, () => (drag = null));
function arrow(x, y, a, len, color) {
  const { k, cx, cy } = view();
  ctx.save(); ctx.translate(cx + x * k, cy - y * k); ctx.rotate(-a); ctx.fillStyle = color;
  ctx.beginPath(); ctx.moveTo(len * k, 0); ctx.lineTo(-0.3 * k, 0.25 * k); ctx.lineTo(-0.3 * k, -0.25 * k); ctx.fill(); ctx.restore();
}
function frame() {
  canvas.width = canvas.clientWidth * devicePixelRatio; canvas.height = canvas.clientHeight * devicePixelRatio;
  lab.step(1); // one step of dt = 1/60 s per frame
  const s = lab.state(), { k, cx, cy } = view(), at = (p) => [cx + p.x * k, cy - p.y * k];
  if (trail.length < 20000) trail.push({ x: s[F.X], y: s[F.Y] });
  ctx.lineWidth = 2 * devicePixelRatio; ctx.strokeStyle = "#c3333a55"; ctx.beginPath(); for (const p of trail) ctx.lineTo(...at(p)); ctx.stroke();
  ctx.strokeStyle = "#2a7"; ctx.beginPath(); ctx.arc(...at(goal), goal.dTol * k, 0, 2 * Math.PI); ctx.stroke(); // the distance tolerance
  arrow(goal.x, goal.y, goal.beta, 1, "#2a7");
  ctx.fillStyle = "#2a7"; ctx.beginPath(); ctx.arc(...at(tip()), 6 * devicePixelRatio, 0, 2 * Math.PI); ctx.fill();
  arrow(s[F.X], s[F.Y], s[F.Theta], 0.4, "#c33");
  const d = Math.hypot(s[F.X] - goal.x, s[F.Y] - goal.y), off = Math.atan2(Math.sin(goal.beta - s[F.Theta]), Math.cos(goal.beta - s[F.Theta]));
  const deg = (a) => ((a * 180) / Math.PI).toFixed(2);
  status.value = `${Mode[s[F.Mode]]} · target (${goal.x.toFixed(2)}, ${goal.y.toFixed(2)}) facing ${deg(goal.beta)}° · ${d.toFixed(3)} m from it · heading off by ${deg(off)}° · ${s[F.V].toFixed(3)} m/s`;
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
