// The collection index: a table of the run's maps, sortable by any column,
// with the sort order kept in the URL fragment (#sort=areas, #sort=-time).
'use strict';

(function () {
  const index = JSON.parse(document.getElementById('index-data').textContent);
  const rows = index.rows || [];

  // The value that each column sorts by; maps without a value sort last.
  const SORT_VALUES = {
    thumbnail: (row) => row.map_name,
    name: (row) => row.map_name,
    areas: (row) => (row.has_area_graph ? row.areas || 0 : undefined),
    passages: (row) => (row.has_area_graph ? row.passages || 0 : undefined),
    width: (row) => row.room_width_m,
    time: (row) => row.compute_s,
    failure: (row) => (row.failure ? (row.failed_stage || '') + ' ' + row.failure : undefined),
  };

  function cell(tr, text, className) {
    const td = document.createElement('td');
    if (className) td.className = className;
    if (text !== undefined) td.textContent = text;
    tr.appendChild(td);
    return td;
  }

  function linkTo(row, child) {
    if (!row.page) return child;
    const anchor = document.createElement('a');
    anchor.href = row.page;
    anchor.appendChild(child);
    return anchor;
  }

  function rowElement(row) {
    const tr = document.createElement('tr');
    tr.dataset.map = row.map_name;
    if (row.failure) tr.className = 'failed';
    const thumb = cell(tr, undefined, 'thumb');
    if (row.thumbnail_png) {
      const image = document.createElement('img');
      image.src = 'data:image/png;base64,' + row.thumbnail_png;
      image.alt = row.map_name;
      thumb.appendChild(linkTo(row, image));
    }
    cell(tr, undefined, 'name').appendChild(linkTo(row, document.createTextNode(row.map_name)));
    cell(tr, row.has_area_graph ? String(row.areas || 0) : '-', 'num');
    cell(tr, row.has_area_graph ? String(row.passages || 0) : '-', 'num');
    cell(tr, row.room_width_m !== undefined
      ? row.room_width_m.toFixed(2) + (row.room_width_automatic ? ' (auto)' : '') : '-', 'num');
    cell(tr, row.compute_s !== undefined ? row.compute_s.toFixed(2) : '-', 'num');
    cell(tr, row.failure ? (row.failed_stage ? row.failed_stage + ': ' : '') + row.failure : '', 'failure');
    return tr;
  }

  function compare(a, b) {
    if (a === b) return 0;
    if (a === undefined) return 1;
    if (b === undefined) return -1;
    if (typeof a === 'number' && typeof b === 'number') return a - b;
    return String(a).localeCompare(String(b), undefined, { numeric: true });
  }

  let sort = { key: 'name', descending: false };

  function render() {
    const value = SORT_VALUES[sort.key] || SORT_VALUES.name;
    const ordered = rows.slice().sort((a, b) => {
      const va = value(a), vb = value(b);
      // Missing values stay last in both directions.
      if (va === undefined || vb === undefined) return compare(va, vb);
      const order = compare(va, vb);
      return sort.descending ? -order : order;
    });
    const body = document.querySelector('#maps tbody');
    body.replaceChildren(...ordered.map(rowElement));
    for (const th of document.querySelectorAll('th[data-key]')) {
      th.classList.toggle('sorted', th.dataset.key === sort.key);
      th.classList.toggle('descending', th.dataset.key === sort.key && sort.descending);
    }
    document.documentElement.dataset.sort = (sort.descending ? '-' : '') + sort.key;
  }

  function readFragment() {
    const match = /(?:^|&)sort=(-?)(\w+)/.exec(location.hash.replace(/^#/, ''));
    if (match && SORT_VALUES[match[2]]) sort = { key: match[2], descending: match[1] === '-' };
  }

  for (const th of document.querySelectorAll('th[data-key]')) {
    th.addEventListener('click', () => {
      sort = { key: th.dataset.key, descending: sort.key === th.dataset.key && !sort.descending };
      history.replaceState(null, '', '#sort=' + (sort.descending ? '-' : '') + sort.key);
      render();
    });
  }
  window.addEventListener('hashchange', () => { readFragment(); render(); });

  const failed = rows.filter((row) => row.failure).length;
  document.getElementById('title').textContent = index.title || 'areagraph report';
  document.getElementById('summary').textContent = rows.length + ' maps, ' + failed + ' failed, ' +
    rows.reduce((sum, row) => sum + (row.areas || 0), 0) + ' areas, ' +
    rows.reduce((sum, row) => sum + (row.passages || 0), 0) + ' passages';
  readFragment();
  render();
  document.documentElement.dataset.ready = String(Math.round(performance.now()));
})();
