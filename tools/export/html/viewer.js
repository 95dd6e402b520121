// The areagraph viewer: draws the page's JSON data (viewer_page.proto) as SVG
// layers over the grid map, with zoom and pan, hover and click information,
// a side panel about the run, and a diff view when the page holds two runs.
// State lives in the URL fragment: #layers=grid,areas&select=area/3&view=side
'use strict';

(function () {
  const SVG_NS = 'http://www.w3.org/2000/svg';

  // Errors and blocked requests are kept on <html data-errors> so that a
  // headless browser's DOM dump shows them.
  const errors = [];
  function recordError(text) {
    errors.push(text);
    document.documentElement.dataset.errors = errors.join(' | ');
  }
  window.addEventListener('error', (event) => recordError('error: ' + event.message));
  document.addEventListener('securitypolicyviolation', (event) =>
    recordError('blocked: ' + event.blockedURI + ' (' + event.violatedDirective + ')'));

  const page = JSON.parse(document.getElementById('page-data').textContent);
  const frame = page.frame;
  const mapWidth = frame.width_px, mapHeight = frame.height_px, resolution = frame.resolution_m;

  // Which layer fields each stage fills; a second run reuses the first run's
  // layers for the stages it shares with it (same_as_first).
  const STAGE_FIELDS = {
    import: ['grid_png'], clean: ['clean'], voronoi: ['voronoi'], prune: ['topology'],
    cut: ['cut', 'room_width'], merge: ['area_graph'],
  };
  const runs = page.runs.map((run, index) => {
    run.index = index;
    run.name = run.label || String.fromCharCode(65 + index);
    run.stageByName = {};
    for (const stage of run.stages || []) {
      run.stageByName[stage.stage] = stage;
      if (stage.same_as_first && index > 0) {
        for (const field of STAGE_FIELDS[stage.stage] || []) run[field] = page.runs[0][field];
      }
    }
    return run;
  });
  const compare = runs.length > 1;

  const LAYERS = [
    { id: 'grid', name: 'Grid map', stage: 'import', on: true },
    { id: 'clean', name: 'Cleaned map: removed outliers and furniture', stage: 'clean' },
    { id: 'hugging', name: 'Voronoi edges hugging obstacles', stage: 'voronoi' },
    { id: 'voronoi', name: 'Voronoi diagram, by clearance', stage: 'voronoi' },
    { id: 'topology', name: 'Topology Graph, by clearance', stage: 'prune' },
    { id: 'rooms', name: 'Room shapes and cut points', stage: 'cut' },
    { id: 'areas', name: 'Areas', stage: 'merge', on: true },
    { id: 'passages', name: 'Passages', stage: 'merge', on: true },
    { id: 'widths', name: 'Doors and corridors (W estimate)', stage: 'cut' },
  ];
  if (compare) LAYERS.push({ id: 'compare', name: 'B over A: areas and passages of B', stage: 'merge' });
  const LAYER_IDS = LAYERS.map((layer) => layer.id);

  const state = {
    layers: new Set(LAYERS.filter((layer) => layer.on).map((layer) => layer.id)),
    select: null, // {run, kind, id}
    view: compare ? 'side' : 'a',
    k: 1, tx: 0, ty: 0,
  };

  // ---- small helpers ----------------------------------------------------

  function svg(name, attributes, parent) {
    const element = document.createElementNS(SVG_NS, name);
    for (const key in attributes) element.setAttribute(key, attributes[key]);
    if (parent) parent.appendChild(element);
    return element;
  }

  function html(name, attributes, parent, text) {
    const element = document.createElement(name);
    for (const key in attributes || {}) element.setAttribute(key, attributes[key]);
    if (text !== undefined) element.textContent = text;
    if (parent) parent.appendChild(element);
    return element;
  }

  // Well separated colours for ids (golden-angle hues), as in ag-render.
  function idColour(id, lightness) {
    return 'hsl(' + ((id * 137.508) % 360).toFixed(1) + ',65%,' + (lightness || 55) + '%)';
  }

  // The id shown for an area or passage: its stable id (kept across the map's
  // versions) when the graph has them, else its index in the graph.
  function shownId(item) {
    return item.stable_id !== undefined ? item.stable_id : item.id;
  }

  function metres(value, digits) {
    return value === undefined ? '-' : value.toFixed(digits === undefined ? 2 : digits) + ' m';
  }

  function shortKey(key) { return key ? key.slice(0, 12) : '-'; }

  function selectKey(selection) {
    if (!selection) return '';
    return (selection.run > 0 ? 'b/' : '') + selection.kind + '/' + selection.id;
  }

  function parseSelectKey(text) {
    const parts = (text || '').split('/');
    let run = 0;
    if (parts[0] === 'b' && compare) { run = 1; parts.shift(); }
    if (parts.length !== 2 || parts[1] === '' || isNaN(Number(parts[1]))) return null;
    return { run: run, kind: parts[0], id: Number(parts[1]) };
  }

  // ---- layers -------------------------------------------------------------

  const BUILDERS = {
    grid(group, run) {
      if (!run.grid_png) return;
      svg('image', {
        href: 'data:image/png;base64,' + run.grid_png, x: 0, y: 0, width: mapWidth,
        height: mapHeight, class: 'grid-image', preserveAspectRatio: 'none',
      }, group);
    },
    clean(group, run) {
      const clean = run.clean;
      if (!clean) return;
      const image = svg('image', {
        x: 0, y: 0, width: mapWidth, height: mapHeight, class: 'clean-image', preserveAspectRatio: 'none',
      }, group);
      colourChanges(clean.changes_png, (url) => image.setAttribute('href', url));
      if (clean.furniture_outlines) svg('path', { d: clean.furniture_outlines, class: 'furniture' }, group);
    },
    voronoi(group, run) {
      const voronoi = run.voronoi;
      if (!voronoi) return;
      group.classList.add('voronoi');
      for (const bucket of voronoi.buckets || []) {
        svg('path', { d: bucket.path, stroke: bucket.colour }, group);
      }
    },
    hugging(group, run) {
      const hugging = (run.voronoi || {}).hugging;
      if (!hugging) return;
      group.classList.add('voronoi');
      svg('path', { d: hugging.path, stroke: hugging.colour }, group);
    },
    topology(group, run) {
      const topology = run.topology;
      if (!topology) return;
      group.classList.add('topology');
      if (topology.boundary) svg('path', { d: topology.boundary, class: 'boundary' }, group);
      for (const bucket of topology.clearance_buckets || []) {
        svg('path', { d: bucket.path, stroke: bucket.colour, class: 'band' }, group);
      }
      for (const edge of topology.edges || []) {
        svg('path', { d: edge.path, class: 'hit', 'data-sel': 'edge/' + edge.id }, group);
      }
      for (const vertex of topology.vertices || []) {
        svg('circle', {
          cx: vertex.x, cy: vertex.y, r: 3, 'data-r': vertex.kind === 'passage' ? 2.5 : 3.5,
          class: 'vertex ' + vertex.kind,
        }, group);
      }
    },
    rooms(group, run) {
      const cut = run.cut;
      if (!cut) return;
      for (const room of cut.rooms || []) {
        svg('path', {
          d: room.path, class: 'room', fill: idColour(room.id), stroke: idColour(room.id, 35),
          'data-sel': 'room/' + room.id,
        }, group);
      }
      const edges = svg('g', { class: 'cut-edges' }, group);
      for (const edge of cut.edges || []) {
        const room = edge.room_id === undefined ? -1 : edge.room_id;
        svg('path', { d: edge.path, class: 'line', stroke: room >= 0 ? idColour(room, 35) : '#555' }, edges);
        svg('path', { d: edge.path, class: 'hit', 'data-sel': 'cutedge/' + edge.id }, edges);
      }
      for (const point of cut.cut_points || []) {
        svg('circle', {
          cx: point.x, cy: point.y, r: 4, 'data-r': 4.5, class: 'cut-point', 'data-sel': 'cut/' + point.id,
        }, group);
      }
    },
    areas(group, run) {
      const graph = run.area_graph;
      if (!graph) return;
      for (const area of graph.areas || []) {
        svg('path', {
          d: area.path, class: 'area', fill: idColour(shownId(area)), stroke: idColour(shownId(area), 30),
          'data-sel': 'area/' + area.id, 'data-id': area.id,
        }, group);
      }
      const labels = svg('g', { class: 'labels' }, group);
      for (const area of graph.areas || []) {
        if (!area.label_at) continue;
        svg('text', { x: area.label_at.x, y: area.label_at.y, class: 'area-label' }, labels)
          .textContent = String(shownId(area));
      }
    },
    passages(group, run) {
      const graph = run.area_graph;
      if (!graph) return;
      for (const passage of graph.passages || []) {
        if (!passage.a || !passage.b) continue;  // a passage without its segment: nothing to draw
        const ends = { x1: passage.a.x, y1: passage.a.y, x2: passage.b.x, y2: passage.b.y };
        svg('line', Object.assign({ class: 'passage-hit', 'data-sel': 'passage/' + passage.id }, ends), group);
        svg('line', Object.assign({ class: 'passage', 'data-sel': 'passage/' + passage.id, 'data-id': passage.id }, ends), group);
      }
    },
    widths(group, run) {
      const width = run.room_width;
      if (!width) return;
      (width.corridors || []).forEach((corridor, index) => {
        svg('circle', {
          cx: corridor.x, cy: corridor.y, r: 4, 'data-r': 4, class: 'corridor', 'data-sel': 'corridor/' + index,
        }, group);
      });
      (width.doors || []).forEach((door, index) => {
        svg('circle', {
          cx: door.x, cy: door.y, r: Math.max(door.width_m / resolution / 2, 1.5),
          class: 'door' + (door.counted ? '' : ' left-out'), 'data-sel': 'door/' + index,
        }, group);
      });
    },
    compare(group, run, view) {
      // Drawn in A's view only: the other run's areas and passages on top.
      const other = runs[1];
      if (!compare || view.run.index !== 0 || !other.area_graph) return;
      group.classList.add('compare');
      for (const area of other.area_graph.areas || []) {
        svg('path', { d: area.path, class: 'area-outline', 'data-sel': 'b/area/' + area.id }, group);
      }
      for (const passage of other.area_graph.passages || []) {
        if (!passage.a || !passage.b) continue;
        svg('line', {
          x1: passage.a.x, y1: passage.a.y, x2: passage.b.x, y2: passage.b.y, class: 'passage-b',
          'data-sel': 'b/passage/' + passage.id,
        }, group);
      }
    },
  };

  // The cleaning codes of viewer_page.proto's CleanChange, as RGBA.
  const CLEAN_COLOURS = [[0, 0, 0, 0], [230, 40, 40, 255], [255, 150, 0, 255], [60, 200, 230, 200]];

  // Colours the grey PNG of cleaning codes through a canvas and hands the
  // result on as a data: URL (the page may load nothing else).
  function colourChanges(pngBase64, done) {
    const codes = new Image();
    codes.onload = () => {
      const canvas = document.createElement('canvas');
      canvas.width = codes.naturalWidth;
      canvas.height = codes.naturalHeight;
      const context = canvas.getContext('2d');
      context.drawImage(codes, 0, 0);
      const pixels = context.getImageData(0, 0, canvas.width, canvas.height);
      const data = pixels.data;
      for (let i = 0; i < data.length; i += 4) {
        const colour = CLEAN_COLOURS[data[i]] || CLEAN_COLOURS[0];
        data[i] = colour[0];
        data[i + 1] = colour[1];
        data[i + 2] = colour[2];
        data[i + 3] = colour[3];
      }
      context.putImageData(pixels, 0, 0);
      done(canvas.toDataURL('image/png'));
    };
    codes.onerror = () => recordError('cannot decode the cleaning layer');
    codes.src = 'data:image/png;base64,' + pngBase64;
  }

  function layerPresent(run, layerId) {
    const layer = LAYERS.find((l) => l.id === layerId);
    if (layerId === 'compare') return compare && !!runs[1].area_graph;
    return !!run.stageByName[layer.stage];
  }

  // ---- map views ------------------------------------------------------------

  class MapView {
    constructor(parent, run, showLabel) {
      this.run = run;
      this.element = html('div', { class: 'view', 'data-run': run.name }, parent);
      if (showLabel) {
        const stage = run.stageByName.merge || run.stages[run.stages.length - 1];
        html('div', { class: 'view-label' }, this.element, run.name + (stage ? ': ' + shortKey(stage.cache_key) : ''));
      }
      this.svg = svg('svg', { 'aria-label': 'map ' + run.name }, this.element);
      this.viewport = svg('g', { class: 'viewport' }, this.svg);
      this.groups = {};
      for (const id of LAYER_IDS) {
        this.groups[id] = svg('g', { class: 'layer', 'data-layer': id, display: 'none' }, this.viewport);
      }
      this.highlight = svg('g', { class: 'highlight' }, this.viewport);
      this.scalebar = svg('g', { class: 'scalebar' }, this.svg);
      this.built = new Set();
      attachPointer(this);
    }

    showLayers() {
      for (const id of LAYER_IDS) {
        const on = state.layers.has(id);
        if (on && !this.built.has(id)) {
          BUILDERS[id](this.groups[id], this.run, this);
          this.built.add(id);
        }
        this.groups[id].setAttribute('display', on ? 'inline' : 'none');
      }
    }

    applyTransform() {
      this.viewport.setAttribute('transform', 'translate(' + state.tx + ' ' + state.ty + ') scale(' + state.k + ')');
      for (const circle of this.viewport.querySelectorAll('circle[data-r]')) {
        circle.setAttribute('r', Number(circle.dataset.r) / state.k);
      }
      for (const labels of this.viewport.querySelectorAll('g.labels')) {
        labels.style.fontSize = (12 / state.k) + 'px';
        labels.style.strokeWidth = (3 / state.k) + 'px';
      }
      drawScaleBar(this);
    }
  }

  // A bar of 1, 2 or 5 times a power of ten metres, at most 160 px long.
  function drawScaleBar(view) {
    const group = view.scalebar;
    group.replaceChildren();
    const height = view.svg.clientHeight || 600;
    const pixelsPerMetre = state.k / resolution;
    let length = Math.pow(10, Math.floor(Math.log10(160 / pixelsPerMetre)));
    for (const factor of [5, 2, 1]) {
      if (length * factor * pixelsPerMetre <= 160) { length *= factor; break; }
    }
    const bar = length * pixelsPerMetre;
    const x = 12, y = height - 16;
    svg('rect', { x: x - 6, y: y - 20, width: bar + 12, height: 28, rx: 3 }, group);
    svg('line', { x1: x, y1: y, x2: x + bar, y2: y }, group);
    svg('line', { x1: x, y1: y - 5, x2: x, y2: y + 3 }, group);
    svg('line', { x1: x + bar, y1: y - 5, x2: x + bar, y2: y + 3 }, group);
    const text = length >= 1000 ? length / 1000 + ' km' : length >= 1 ? length + ' m' : Math.round(length * 100) + ' cm';
    svg('text', { x: x, y: y - 8, class: 'scalebar-text' }, group).textContent = text;
    group.dataset.metres = String(length);
  }

  let views = [];
  function applyTransforms() {
    for (const view of views) view.applyTransform();
  }

  function fitMap() {
    const box = views[0].svg.getBoundingClientRect();
    const width = box.width || 800, height = box.height || 600;
    state.k = Math.min(width / mapWidth, height / mapHeight) * 0.96;
    state.tx = (width - mapWidth * state.k) / 2;
    state.ty = (height - mapHeight * state.k) / 2;
    applyTransforms();
  }

  function attachPointer(view) {
    const element = view.svg;
    let drag = null;
    element.addEventListener('wheel', (event) => {
      event.preventDefault();
      const box = element.getBoundingClientRect();
      const x = event.clientX - box.left, y = event.clientY - box.top;
      const factor = Math.exp(-event.deltaY * 0.0015);
      const k = Math.min(Math.max(state.k * factor, 0.02), 200);
      state.tx = x - (x - state.tx) * (k / state.k);
      state.ty = y - (y - state.ty) * (k / state.k);
      state.k = k;
      applyTransforms();
    }, { passive: false });
    element.addEventListener('pointerdown', (event) => {
      if (event.button !== 0) return;
      drag = { x: event.clientX, y: event.clientY, tx: state.tx, ty: state.ty, moved: false, target: event.target };
      try {
        element.setPointerCapture(event.pointerId);
      } catch (error) {
        // A synthetic event has no pointer to capture; dragging still works inside the view.
      }
    });
    element.addEventListener('pointermove', (event) => {
      if (!drag) {
        const target = event.target.closest && event.target.closest('[data-sel]');
        showInfo(target ? selectionOf(target, view) : state.select, !!target);
        return;
      }
      const dx = event.clientX - drag.x, dy = event.clientY - drag.y;
      if (Math.abs(dx) + Math.abs(dy) > 3) { drag.moved = true; element.classList.add('panning'); }
      if (drag.moved) {
        state.tx = drag.tx + dx;
        state.ty = drag.ty + dy;
        applyTransforms();
      }
    });
    element.addEventListener('pointerup', (event) => {
      if (drag && !drag.moved && !routes.click(view, event)) {
        const target = drag.target.closest && drag.target.closest('[data-sel]');
        select(target ? selectionOf(target, view) : null);
      }
      drag = null;
      element.classList.remove('panning');
    });
    element.addEventListener('pointerleave', () => { if (!drag) showInfo(state.select, false); });
    element.addEventListener('dblclick', fitMap);
  }

  function selectionOf(element, view) {
    const selection = parseSelectKey(element.getAttribute('data-sel'));
    if (selection && !element.getAttribute('data-sel').startsWith('b/')) selection.run = view.run.index;
    return selection;
  }

  // ---- selection and information ---------------------------------------------

  function findItem(run, kind, id) {
    const graph = run.area_graph || {}, cut = run.cut || {}, width = run.room_width || {};
    const byId = (list) => (list || []).find((item) => item.id === id);
    switch (kind) {
      case 'area': return byId(graph.areas);
      case 'passage': return byId(graph.passages);
      case 'edge': return byId((run.topology || {}).edges);
      case 'cutedge': return byId(cut.edges);
      case 'room': return byId(cut.rooms);
      case 'cut': return byId(cut.cut_points);
      case 'door': return (width.doors || [])[id];
      case 'corridor': return (width.corridors || [])[id];
    }
    return undefined;
  }

  function link(parent, kind, id, runIndex, text) {
    const anchor = html('a', { class: 'select-link', 'data-link': (runIndex > 0 ? 'b/' : '') + kind + '/' + id }, parent, text);
    anchor.addEventListener('click', () => select({ run: runIndex, kind: kind, id: id }));
    return anchor;
  }

  function row(table, name, value) {
    const tr = html('tr', {}, table);
    html('th', {}, tr, name);
    const td = html('td', {}, tr);
    if (value instanceof Node) td.appendChild(value); else td.textContent = value;
    return td;
  }

  // The id an item is shown by (areas and passages: their stable id), from
  // its index.
  function shownIdOf(run, kind, id) {
    const item = (kind === 'area' || kind === 'passage') ? findItem(run, kind, id) : undefined;
    return item ? shownId(item) : id;
  }

  function linkList(run, kind, ids, describe) {
    const span = document.createElement('span');
    if (!ids || ids.length === 0) { span.textContent = 'none'; return span; }
    ids.forEach((id, i) => {
      if (i > 0) span.appendChild(document.createTextNode(', '));
      link(span, kind, id, run.index, String(shownIdOf(run, kind, id)));
      if (describe) span.appendChild(document.createTextNode(describe(id)));
    });
    return span;
  }

  const DESCRIBE = {
    area(run, area, table) {
      row(table, 'kind', area.kind.replace('_', ' '));
      row(table, 'area', (area.area_m2 || 0).toFixed(2) + ' m²');
      row(table, 'topology edges', linkList(run, 'cutedge', area.topology_edge_ids));
      row(table, 'passages', linkList(run, 'passage', area.passage_ids, (id) => {
        const passage = findItem(run, 'passage', id);
        if (!passage) return '';
        const other = passage.area_a === area.id ? passage.area_b : passage.area_a;
        return ' (' + metres(passage.width_m) + ' to area ' + shownIdOf(run, 'area', other) + ')';
      }));
      if (area.stable_id !== undefined) row(table, 'index in this version', String(area.id));
      return 'Area ' + shownId(area);
    },
    passage(run, passage, table) {
      row(table, 'width', metres(passage.width_m));
      const between = document.createElement('span');
      link(between, 'area', passage.area_a, run.index, 'area ' + shownIdOf(run, 'area', passage.area_a));
      between.appendChild(document.createTextNode(' and '));
      link(between, 'area', passage.area_b, run.index, 'area ' + shownIdOf(run, 'area', passage.area_b));
      row(table, 'between', between);
      if (passage.stable_id !== undefined) row(table, 'index in this version', String(passage.id));
      return 'Passage ' + shownId(passage);
    },
    door(run, door, table) {
      const width = run.room_width;
      row(table, 'width', metres(door.width_m));
      row(table, 'counted', door.counted
        ? 'yes: at most the widest door taken (' + metres(width.widest_door_m) + ')'
        : 'no: wider than the widest door taken (' + metres(width.widest_door_m) + '), left out as a stray');
      if (Math.abs(door.width_m - width.widest_door_m) < 1e-6) row(table, 'note', 'this width is the widest door');
      return 'Door';
    },
    corridor(run, corridor, table) {
      row(table, 'width', metres(corridor.width_m));
      row(table, 'length', metres(corridor.length_m, 1));
      return 'Corridor';
    },
    edge(run, edge, table) {
      row(table, 'length', metres(edge.length_m));
      row(table, 'min clearance', metres(edge.min_clearance_m) + ' (gap about ' + metres(2 * edge.min_clearance_m) + ')');
      return 'Topology edge ' + edge.id;
    },
    cutedge(run, edge, table) {
      row(table, 'room', edge.room_id === undefined ? 'none (between rooms)' : 'room shape ' + edge.room_id);
      row(table, 'length', metres(edge.length_m));
      row(table, 'min clearance', metres(edge.min_clearance_m));
      const areas = ((run.area_graph || {}).areas || []).filter((area) => (area.topology_edge_ids || []).includes(edge.id));
      row(table, 'in area', linkList(run, 'area', areas.map((area) => area.id)));
      return 'Cut graph edge ' + edge.id;
    },
    room(run, room, table) {
      const edges = ((run.cut || {}).edges || []).filter((edge) => edge.room_id === room.id);
      row(table, 'edges', linkList(run, 'cutedge', edges.map((edge) => edge.id)));
      return 'Room shape ' + room.id;
    },
    cut(run, point, table) {
      row(table, 'width', metres(point.width_m));
      return 'Cut point ' + point.id;
    },
  };

  let shownInfo = null;
  function showInfo(selection, hovering) {
    const info = document.getElementById('info');
    // Pointer moves within one element redraw nothing.
    const shown = selectKey(selection) + (hovering ? ' hover' : '');
    if (shown === shownInfo && info.childElementCount > 0) return;
    shownInfo = shown;
    delete info.dataset.selected;
    delete info.dataset.hovering;
    if (!selection) {
      info.className = 'muted';
      info.textContent = 'Hover over or click an area, passage, door, corridor, edge, room shape or cut point.';
      return;
    }
    const run = runs[selection.run] || runs[0];
    const item = findItem(run, selection.kind, selection.id);
    info.replaceChildren();
    info.className = '';
    if (!item || !DESCRIBE[selection.kind]) {
      info.textContent = 'No ' + selection.kind + ' ' + selection.id + ' in run ' + run.name + '.';
      return;
    }
    const title = html('div', { class: 'title' }, info);
    const table = html('table', {}, info);
    title.textContent = DESCRIBE[selection.kind](run, item, table) + (compare ? ' (' + run.name + ')' : '');
    info.dataset.selected = selectKey(selection);
    info.dataset.hovering = hovering ? 'yes' : 'no';
  }

  function highlightSelection() {
    for (const view of views) {
      view.highlight.replaceChildren();
      for (const element of view.svg.querySelectorAll('.selected')) element.classList.remove('selected');
    }
    const selection = state.select;
    if (!selection) return;
    for (const view of views) {
      // The selected run's own view, or A's view with B drawn over it.
      const own = view.run.index === selection.run;
      if (!own && !(view.run.index === 0 && selection.run === 1)) continue;
      const key = (own ? '' : 'b/') + selection.kind + '/' + selection.id;
      for (const element of view.svg.querySelectorAll('[data-sel="' + key + '"]')) {
        if (!element.classList.contains('hit') && !element.classList.contains('passage-hit')) element.classList.add('selected');
      }
      const run = runs[selection.run];
      let edgeIds = [];
      if (selection.kind === 'area') edgeIds = (findItem(run, 'area', selection.id) || {}).topology_edge_ids || [];
      if (selection.kind === 'cutedge') edgeIds = [selection.id];
      for (const id of edgeIds) {
        const edge = findItem(run, 'cutedge', id);
        if (edge) svg('path', { d: edge.path }, view.highlight);
      }
      if (selection.kind === 'edge') {
        const edge = findItem(run, 'edge', selection.id);
        if (edge) svg('path', { d: edge.path }, view.highlight);
      }
    }
  }

  function select(selection) {
    state.select = selection;
    highlightSelection();
    showInfo(selection, false);
    writeFragment();
  }

  // ---- side panel ----------------------------------------------------------

  function buildLayerControls() {
    const container = document.getElementById('layers');
    container.replaceChildren();
    for (const layer of LAYERS) {
      const present = runs.some((run) => layerPresent(run, layer.id));
      const rowElement = html('div', { class: 'layer-row' + (present ? '' : ' absent') }, container);
      const box = html('input', { type: 'checkbox', id: 'layer-' + layer.id, 'data-layer': layer.id }, rowElement);
      box.checked = state.layers.has(layer.id);
      box.disabled = !present;
      html('label', { for: 'layer-' + layer.id }, rowElement, layer.name + (present ? '' : ' (not in the store)'));
      box.addEventListener('change', () => {
        if (box.checked) state.layers.add(layer.id); else state.layers.delete(layer.id);
        applyLayers();
        writeFragment();
      });
      const legend = LEGENDS[layer.id] && present ? LEGENDS[layer.id]() : null;
      if (legend) {
        legend.dataset.legendFor = layer.id;
        container.appendChild(legend);
      }
    }
  }

  function legendOf(items) {
    const legend = html('div', { class: 'legend' });
    for (const [colour, text] of items) {
      const entry = html('div', {}, legend);
      html('span', { class: 'swatch', style: 'background:' + colour }, entry);
      entry.appendChild(document.createTextNode(text));
    }
    return legend;
  }

  const LEGENDS = {
    clean: () => legendOf([['rgb(230,40,40)', 'outliers removed'], ['rgb(255,150,0)', 'furniture removed'],
      ['rgb(60,200,230)', 'unknown islands made free']]),
    hugging: () => legendOf(((runs[0].voronoi || {}).hugging ? [runs[0].voronoi.hugging] : []).map((b) => [b.colour, 'clearance under 2 px: most of the diagram, not its skeleton'])),
    voronoi: () => legendOf(((runs[0].voronoi || {}).buckets || []).map((b) => [b.colour, 'clearance ' + b.label])),
    topology: () => legendOf([['#dc1e1e', 'dead end'], ['#821ea0', 'junction'], ['#1e5ac8', 'boundary (dashed)']]),
    widths: () => legendOf([['#c800c8', 'door (ring as wide as the door; dashed: left out)'], ['#00a0c8', 'corridor']]),
    rooms: () => legendOf([['#00aa00', 'cut point (passage point)']]),
    compare: () => legendOf([['#e0007a', 'areas and passages of B']]),
  };

  function table(parent, headers) {
    const element = html('table', {}, parent);
    const tr = html('tr', {}, element);
    for (const header of headers) html('th', { class: header.num ? 'num' : '' }, tr, header.text || header);
    return element;
  }

  function cells(tableElement, values, options) {
    const tr = html('tr', {}, tableElement);
    values.forEach((value, i) => {
      const td = html('td', { class: (options && options.num && i > 0) ? 'num' : '' }, tr, value === undefined ? '-' : String(value));
      if (options && options.differs && i > 0) td.classList.add('differs');
    });
    return tr;
  }

  function countsOf(run) {
    const graph = run.area_graph || {}, cut = run.cut || {}, topology = run.topology || {};
    const voronoi = run.voronoi || {}, clean = run.clean || {}, width = run.room_width || {};
    const areas = graph.areas || [];
    const kinds = (kind) => areas.filter((area) => area.kind === kind).length;
    const vertices = topology.vertices || [];
    const has = (stage) => !!run.stageByName[stage];
    const when = (stage, value) => (has(stage) ? value : undefined);
    return [
      ['areas', when('merge', areas.length)],
      ['  rooms', when('merge', kinds('room'))],
      ['  corridors', when('merge', kinds('corridor'))],
      ['  dead ends', when('merge', kinds('dead_end'))],
      ['passages', when('merge', (graph.passages || []).length)],
      ['room shapes', when('cut', (cut.rooms || []).length)],
      ['cut points', when('cut', (cut.cut_points || []).length)],
      ['doors found', when('cut', (width.doors || []).length)],
      ['corridors found', when('cut', (width.corridors || []).length)],
      ['topology edges', when('prune', (topology.edges || []).length)],
      ['topology vertices', when('prune', vertices.length)],
      ['  dead ends', when('prune', vertices.filter((v) => v.kind === 'dead_end').length)],
      ['Voronoi edges', when('voronoi', voronoi.edges)],
      ['Voronoi vertices', when('voronoi', voronoi.vertices)],
      ['obstacle sites', when('voronoi', voronoi.sites)],
      ['outlier cells removed', when('clean', clean.outlier_cells || 0)],
      ['furniture cells removed', when('clean', clean.furniture_cells || 0)],
      ['unknown cells freed', when('clean', clean.freed_unknown_cells || 0)],
    ];
  }

  function buildCounts() {
    const container = document.getElementById('counts');
    container.replaceChildren();
    const element = table(container, ['', ...runs.map((run) => ({ text: compare ? run.name : 'count', num: true }))]);
    const columns = runs.map(countsOf);
    columns[0].forEach(([name], i) => {
      const values = columns.map((column) => column[i][1]);
      cells(element, [name, ...values], { num: true, differs: compare && values[0] !== values[1] });
    });
  }

  function buildRoomWidth() {
    const container = document.getElementById('room-width');
    container.replaceChildren();
    for (const run of runs) {
      const width = run.room_width;
      const block = html('div', {}, container);
      const prefix = compare ? run.name + ': ' : '';
      if (!width) { block.textContent = prefix + 'no cut stage in this run'; continue; }
      html('div', { class: 'title' }, block, prefix + 'W = ' + metres(width.room_width_m));
      html('div', {}, block, width.rule || '');
      if (width.automatic) {
        const doors = width.doors || [];
        html('div', { class: 'muted' }, block, 'widest door ' + metres(width.widest_door_m) + ', narrowest corridor ' +
          (width.narrowest_corridor_m > 0 ? metres(width.narrowest_corridor_m) : 'none') + '; ' + doors.length + ' doors (' +
          doors.filter((door) => door.counted).length + ' counted), ' + (width.corridors || []).length + ' corridors');
      }
    }
  }

  function buildStages() {
    const container = document.getElementById('stages');
    container.replaceChildren();
    const headers = ['stage'];
    for (const run of runs) headers.push((compare ? run.name + ' ' : '') + 'key', { text: 'ms', num: true });
    const element = table(container, headers);
    for (const name of Object.keys(STAGE_FIELDS)) {
      if (!runs.some((run) => run.stageByName[name])) continue;
      const tr = html('tr', {}, element);
      html('td', {}, tr, name);
      for (const run of runs) {
        const stage = run.stageByName[name];
        const key = html('td', { class: 'key', title: stage ? stage.cache_key + ' (version ' + stage.stage_version +
          ', ' + stage.created_at + ', ' + stage.payload_bytes + ' bytes)' : '' }, tr, stage ? shortKey(stage.cache_key) : '-');
        if (run.index > 0 && stage && !stage.same_as_first) key.classList.add('differs');
        html('td', { class: 'num' }, tr, stage ? (stage.elapsed_ms || 0).toFixed(1) : '-');
      }
    }
    const totals = runs.map((run) => (run.stages || []).reduce((sum, stage) => sum + (stage.elapsed_ms || 0), 0));
    html('div', { class: 'muted' }, container, 'compute time: ' + totals.map((t) => (t / 1000).toFixed(2) + ' s').join(' / ') +
      '; created ' + (((runs[0].stages || [])[0] || {}).created_at || '-'));
  }

  function buildOptions() {
    const container = document.getElementById('options');
    container.replaceChildren();
    const element = table(container, ['option', ...runs.map((run) => (compare ? run.name : 'value'))]);
    for (const name of Object.keys(STAGE_FIELDS)) {
      const perRun = runs.map((run) => (run.stageByName[name] || {}).options || []);
      const names = perRun.find((list) => list.length) || [];
      for (const option of names) {
        const values = perRun.map((list) => list.find((o) => o.name === option.name));
        const tr = html('tr', {}, element);
        html('td', {}, tr, name + '.' + option.name);
        const differs = compare && values[1] && values[0] && values[0].value !== values[1].value;
        for (const value of values) {
          const td = html('td', {}, tr, value ? value.value : '-');
          if (value && !value.is_default) {
            td.classList.add('non-default');
            td.title = 'default: ' + value.default_value;
          }
          if (differs) td.classList.add('differs');
        }
      }
    }
    html('div', { class: 'muted' }, container, 'Highlighted: differs from the default (hover for it).' +
      (compare ? ' Red: differs between A and B.' : ''));
  }

  function buildDiff() {
    if (!compare) return;
    const section = document.getElementById('diff-section');
    section.hidden = false;
    const container = document.getElementById('diff');
    container.replaceChildren();
    const modes = [['a', 'A only'], ['b', 'B only'], ['side', 'side by side'], ['overlay', 'B over A']];
    const choices = html('div', {}, container);
    for (const [mode, text] of modes) {
      const label = html('label', { style: 'margin-right:10px' }, choices);
      const radio = html('input', { type: 'radio', name: 'view', value: mode, 'data-view': mode }, label);
      radio.checked = state.view === mode;
      radio.addEventListener('change', () => { setView(mode); writeFragment(); });
      label.appendChild(document.createTextNode(' ' + text));
    }
    const differing = Object.keys(STAGE_FIELDS).filter((name) => runs[1].stageByName[name] && !runs[1].stageByName[name].same_as_first);
    html('div', {}, container, differing.length ? 'Stages that differ: ' + differing.join(', ') : 'Both runs share every artifact.');
  }

  // ---- views and state --------------------------------------------------------

  function setView(mode) {
    state.view = compare ? mode : 'a';
    const container = document.getElementById('views');
    container.replaceChildren();
    const shown = state.view === 'side' ? [runs[0], runs[1]] : state.view === 'b' ? [runs[1]] : [runs[0]];
    views = shown.map((run) => new MapView(container, run, compare));
    routes.redraw();
    if (state.view === 'overlay') state.layers.add('compare');
    for (const box of document.querySelectorAll('input[data-view]')) box.checked = box.value === state.view;
    applyLayers();
    fitMap();
    highlightSelection();
  }

  function applyLayers() {
    for (const view of views) view.showLayers();
    for (const box of document.querySelectorAll('input[data-layer]')) box.checked = state.layers.has(box.dataset.layer);
    for (const legend of document.querySelectorAll('[data-legend-for]')) legend.hidden = !state.layers.has(legend.dataset.legendFor);
    applyTransforms();
    highlightSelection();
    document.documentElement.dataset.layers = [...state.layers].join(',');
  }

  function readFragment() {
    const values = {};
    for (const part of location.hash.replace(/^#/, '').split('&')) {
      const at = part.indexOf('=');
      if (at > 0) values[part.slice(0, at)] = decodeURIComponent(part.slice(at + 1));
    }
    if (values.layers !== undefined) {
      state.layers = new Set(values.layers.split(',').filter((id) => LAYER_IDS.includes(id)));
    }
    if (values.view && ['a', 'b', 'side', 'overlay'].includes(values.view)) state.view = compare ? values.view : 'a';
    state.select = values.select ? parseSelectKey(values.select) : null;
  }

  function writeFragment() {
    const parts = ['layers=' + [...state.layers].join(',')];
    if (compare) parts.push('view=' + state.view);
    if (state.select) parts.push('select=' + selectKey(state.select));
    history.replaceState(null, '', '#' + parts.join('&'));
  }

  function applyFragment() {
    readFragment();
    buildLayerControls();
    setView(state.view);
    showInfo(state.select, false);
  }

  // ---- start ---------------------------------------------------------------------

  document.getElementById('map-name').textContent = page.map_name;
  document.getElementById('map-size').textContent = mapWidth + ' × ' + mapHeight + ' px, ' + resolution +
    ' m/px (' + (mapWidth * resolution).toFixed(1) + ' × ' + (mapHeight * resolution).toFixed(1) + ' m)';
  buildDiff();
  buildRoomWidth();
  buildCounts();
  buildStages();
  buildOptions();
  // Routes between two clicked points (route.js).
  const routes = areagraphRoutes({ state, resolution, svg, html, views: () => views });
  applyFragment();
  window.addEventListener('hashchange', applyFragment);
  window.addEventListener('resize', applyTransforms);
  // For tests and tools/bench-viewer.sh: the script ran to its end, this many
  // milliseconds after the navigation started.
  document.documentElement.dataset.ready = String(Math.round(performance.now()));
})();
