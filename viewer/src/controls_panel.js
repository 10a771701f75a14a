// The replay's controls: play/pause, time slider and readout, speed, camera
// follow, one checkbox per sensor, the legend of the ray colours (status), the
// strategy's events, and the terrain map's toggle, height scale and hazards.
const SPEEDS = [0.25, 0.5, 1, 2, 4, 8];

function el(tag, attrs = {}, children = []) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'text') e.textContent = v; else e.setAttribute(k, v);
  }
  for (const c of children) e.appendChild(c);
  return e;
}

export class ControlsPanel {
  /** handlers: {onPlayToggle(), onSeek(t), onSpeed(x), onSensor(j, on), onFollow(on), onTerrain(on)} */
  constructor(bar, side, data, span, step, handlers) {
    this.span = span;
    this.playButton = el('button', { class: 'proxsim-play', title: 'play / pause (space)', text: '▶ Play' });
    this.playButton.addEventListener('click', () => handlers.onPlayToggle());
    this.slider = el('input', { type: 'range', class: 'proxsim-slider', min: String(span[0]),
      max: String(span[1]), step: String(step), value: String(span[0]) });
    this.slider.addEventListener('input', () => handlers.onSeek(Number(this.slider.value)));
    this.readout = el('span', { class: 'proxsim-time' });
    const speed = el('select', { class: 'proxsim-speed', title: 'replay speed' },
      SPEEDS.map((x) => el('option', { value: String(x), text: `${x}×` })));
    speed.value = '1';
    speed.addEventListener('change', () => handlers.onSpeed(Number(speed.value)));
    const follow = el('input', { type: 'checkbox', class: 'proxsim-follow' });
    follow.checked = Boolean(data.poses);
    follow.addEventListener('change', () => handlers.onFollow(follow.checked));
    bar.append(this.playButton, this.slider, this.readout, el('label', { text: 'speed ' }, [speed]),
      el('label', { title: 'the camera follows the robot' }, [follow, document.createTextNode(' follow')]));

    // sensors
    side.appendChild(el('h3', { text: 'Sensors' }));
    data.sensors.forEach((s, j) => {
      const box = el('input', { type: 'checkbox', class: 'proxsim-sensor-toggle', 'data-sensor': s.name });
      box.checked = true;
      box.addEventListener('change', () => handlers.onSensor(j, box.checked));
      side.appendChild(el('label', { class: 'proxsim-row' }, [
        box, el('span', { class: 'proxsim-swatch', style: `background:${s.color}` }),
        document.createTextNode(` ${s.name} `), el('small', { text: s.type })]));
    });
    // ray colours
    side.appendChild(el('h3', { text: 'Ray status' }));
    data.statuses.forEach((_, k) => {
      side.appendChild(el('div', { class: 'proxsim-row' }, [
        el('span', { class: 'proxsim-swatch proxsim-ray', style: `background:${data.statusColors[k]}` }),
        document.createTextNode(` ${data.statusLabels[k]}`)]));
    });
    // the strategy's events: click one to go to its time
    this.events = [];
    if ((data.events || []).length) {
      side.appendChild(el('h3', { text: 'Strategy events' }));
      for (const e of data.events) {
        const row = el('div', { class: 'proxsim-row proxsim-event', title: e.detail,
          text: `${e.t.toFixed(2)} s  ${e.event.replace(/_/g, ' ')}` });
        row.addEventListener('click', () => handlers.onSeek(e.t));
        side.appendChild(row);
        this.events.push([e.t, row]);
      }
    }
    this.hazards = [];
    if (data.terrain) this.addTerrain(side, data.terrain, handlers);
    side.appendChild(el('p', { class: 'proxsim-hint',
      text: `Dots: profile points, coloured by object.${data.terrain ? ' Squares under them: the map\'s cells.' : ''}`
        + ' Drag to orbit, wheel to zoom, right-drag to pan.' }));
  }

  /** The terrain map's rows: its toggle, its height scale, one row per hazard
   *  (click one to go to the time it was found). */
  addTerrain(side, terrain, handlers) {
    side.appendChild(el('h3', { text: 'Terrain map' }));
    const box = el('input', { type: 'checkbox', class: 'proxsim-terrain-toggle' });
    box.checked = true;
    box.addEventListener('change', () => handlers.onTerrain(box.checked));
    side.appendChild(el('label', { class: 'proxsim-row' }, [box, document.createTextNode(' cells measured, by height')]));
    const [lo, hi] = terrain.zRange;
    side.appendChild(el('div', { class: 'proxsim-row' }, [
      el('small', { text: `${lo.toFixed(2)} m` }),
      el('span', { class: 'proxsim-scale', style: `background:linear-gradient(to right, ${terrain.colorStops.join(', ')})` }),
      el('small', { text: `${hi.toFixed(2)} m` })]));
    // the hazards in a list of their own, scrolled when long (a stairs course finds dozens)
    const list = el('div', { class: 'proxsim-hazard-list' });
    side.appendChild(list);
    for (const h of terrain.hazards) {
      const found = h.t === null ? '' : ` at ${h.t.toFixed(2)} s`;
      const ahead = h.distance === null ? '' : `, ${h.distance.toFixed(2)} m ahead`;
      const row = el('div', { class: 'proxsim-row proxsim-hazard', title: `found${found}${ahead}` }, [
        el('span', { class: 'proxsim-swatch', style: `background:${h.color}` }),
        document.createTextNode(` ${h.label} ${h.height >= 0 ? '+' : '−'}${Math.abs(100 * h.height).toFixed(0)} cm${found}`)]);
      if (h.t !== null) row.addEventListener('click', () => handlers.onSeek(h.t));
      list.appendChild(row);
      this.hazards.push([h.t ?? -Infinity, row]);
    }
    if (!terrain.hazards.length) side.appendChild(el('div', { class: 'proxsim-row', text: 'no hazard found' }));
  }

  /** Reflects the time and play state in the widgets. */
  show(t, playing) {
    this.slider.value = String(t);
    this.readout.textContent = `t = ${t.toFixed(2)} s / ${this.span[1].toFixed(2)} s`;
    this.playButton.textContent = playing ? '❚❚ Pause' : '▶ Play';
    for (const [te, row] of this.events) row.classList.toggle('proxsim-event-past', te <= t);
    for (const [th, row] of this.hazards) row.classList.toggle('proxsim-hazard-found', th <= t);
  }
}
