// The distance curves under the 3D view (uPlot): measured distance of every
// sensor over time, one colour per sensor, with a vertical cursor line that
// follows the time shown; a click on the plot jumps to that time.
import uPlot from 'uplot';

export class CurvesView {
  constructor(container, sensors, onPick) {
    this.container = container;
    const tables = sensors.map((s) => [s.t, s.dM]);
    const data = tables.length ? uPlot.join(tables) : [[], []];
    const series = [{ label: 't (s)', value: (u, v) => (v == null ? '–' : v.toFixed(2)) }];
    for (const s of sensors) {
      series.push({
        label: s.name, stroke: s.color, width: 1.25, points: { show: false },
        value: (u, v) => (v == null ? '–' : `${v.toFixed(3)} m`),
      });
    }
    this.plot = new uPlot({
      width: Math.max(container.clientWidth, 200),
      height: Math.max(container.clientHeight - 52, 120),
      series,
      scales: { x: { time: false }, y: { range: (u, lo, hi) => [0, Math.max(hi, 0.1) * 1.05] } },
      axes: [{ label: 'time t (s)' }, { label: 'distance d_m (m)' }],
      cursor: { drag: { x: false, y: false } },
      legend: { live: true },
    }, data, container);

    // the time cursor: a line inside uPlot's overlay, moved by style only
    this.line = document.createElement('div');
    this.line.className = 'proxsim-time-cursor';
    this.plot.over.appendChild(this.line);
    this.plot.over.addEventListener('click', () => {
      const left = this.plot.cursor.left;
      if (left != null && left >= 0) onPick(this.plot.posToVal(left, 'x'));
    });
    this.lastT = null;
  }

  /** Moves the time cursor to t. */
  update(t) {
    if (t === this.lastT) return;
    this.lastT = t;
    this.line.style.left = `${this.plot.valToPos(t, 'x')}px`;
  }

  /** Shows or hides sensor j's curve. */
  setSensorVisible(j, visible) {
    this.plot.setSeries(j + 1, { show: visible });
  }

  resize() {
    this.plot.setSize({ width: Math.max(this.container.clientWidth, 200),
      height: Math.max(this.container.clientHeight - 52, 120) });
    this.lastT = null;
  }
}
