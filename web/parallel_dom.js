// The parallel DOM (as PhET's sims have): every item the ImGui front end drew in the last
// frame is mirrored by a real, visually hidden HTML element over the canvas where the item is
// drawn, with its role, accessible name and state (web/js_parallel_dom.cpp). A screen reader
// reads them, Tab and Shift+Tab walk them in reading order, and activating one (click, Enter,
// Space) presses the item. A mirrored field is a real <input>: focused, it shows over the
// field, the phone's keyboard opens for it (inputmode="decimal" for numbers), and what is
// typed goes into the item on Enter or when it is left. Pointers still act on the canvas:
// the elements take no pointer events. Linked with --post-js.
(function () {
  'use strict';
  if (typeof document === 'undefined') return;

  var root = null;            // <div id="parallel-dom">
  var regions = new Map();    // window title -> <section>
  var elements = new Map();   // key -> element
  var groups = new Map();     // key -> <div role="tablist|listbox|menubar|menu">
  var lastText = '';
  var editingShown = 0;       // the field being typed into on the canvas, shown as an <input>
  var kMaxFieldChars = 1024;  // what a mirrored field takes (a number, a cell, an answer)

  // An item's id becomes a C unsigned: checked as one first (2^32 + 5 would press item 5).
  function call(name, types, args) {
    var id = args[0];
    if (!Number.isSafeInteger(id) || id < 0 || id > 0xffffffff)
      throw new Error('parallel DOM: ' + name + ': the item id must be an integer from 0 to 4294967295, not ' + String(id));
    Module.ccall(name, null, types, args);
  }
  function activate(id) { call('swarmlab_dom_activate', ['number'], [id]); }
  // Whether the page's last input was a key (Tab, a screen reader's keys) rather than a finger
  // or a mouse: only then does a focus show ImGui's focus ring, and does the focus of an item
  // that goes away move on to the next one. True until a pointer is used: a screen reader in
  // browse mode moves the focus without sending the page its keys.
  var byKeyboard = true;
  function focusItem(id) { call('swarmlab_dom_focus', ['number', 'number'], [id, byKeyboard ? 1 : 0]); }
  function type(id, text, enter) { call('swarmlab_dom_type', ['number', 'string', 'number'], [id, text, enter ? 1 : 0]); }

  function makeRoot() {
    root = document.createElement('div');
    root.id = 'parallel-dom';
    (document.querySelector('main') || document.body).appendChild(root);
    // Where overflow: clip is missing, the box could still be scrolled by a focus: undo it.
    root.addEventListener('scroll', function () { root.scrollTop = 0; root.scrollLeft = 0; });
    // Tab belongs to the page (it walks the mirrored items), not to the canvas's app.
    document.addEventListener('keydown', function (e) { if (e.key === 'Tab') e.stopPropagation(); });
    // Typing into a field (a phone's keyboard too) is not walking the page by keys.
    window.addEventListener('keydown', function (e) {
      if (e.key === 'Tab' || !e.target || e.target.tagName !== 'INPUT') byKeyboard = true;
    }, true);
    window.addEventListener('pointerdown', function () { byKeyboard = false; }, true);
  }

  function regionFor(title) {
    var section = regions.get(title);
    if (!section) {
      section = document.createElement('section');
      section.className = 'pdom-region';
      if (title) section.setAttribute('aria-label', title);
      regions.set(title, section);
      root.appendChild(section);
    }
    return section;
  }

  function isField(role) { return role === 'textbox' || role === 'slider'; }
  // The element an item needs: an <input>, a heading, a paragraph or a <button>.
  function kindOf(item) {
    return isField(item.role) ? 'input' : item.role === 'heading' || item.role === 'paragraph' ? item.role : 'button';
  }

  function commit(el, enter) {
    if (!el.swarmlabDirty) return;
    el.swarmlabDirty = false;
    type(el.swarmlabId, el.value, enter);
  }

  function make(item) {
    var el;
    if (isField(item.role)) {
      el = document.createElement('input');
      el.type = 'text';
      // Typed text crosses on the wasm stack (ccall); ImGui's fields hold far less anyway.
      el.maxLength = kMaxFieldChars;
      el.autocomplete = 'off';
      el.spellcheck = false;
      // ImGui's slider, mirrored as a field its number is typed into: a spinbutton (the role
      // a text <input> may take; a slider's may not).
      if (item.role === 'slider') el.setAttribute('role', 'spinbutton');
      el.setAttribute('enterkeyhint', 'done');
      el.addEventListener('input', function () { el.swarmlabDirty = true; });
      el.addEventListener('keydown', function (e) {
        e.stopPropagation(); // typed characters are not the app's shortcuts
        if (e.key === 'Enter') { e.preventDefault(); el.swarmlabDirty = true; commit(el, true); }
        if (e.key === 'Escape') { el.value = el.swarmlabValue || ''; el.swarmlabDirty = false; el.blur(); }
      });
      el.addEventListener('keypress', function (e) { e.stopPropagation(); });
      el.addEventListener('keyup', function (e) { e.stopPropagation(); });
      el.addEventListener('focus', function () {
        el.classList.add('pdom-editing');
        el.value = el.swarmlabValue || '';
        el.swarmlabDirty = false;
        el.select();
        focusItem(el.swarmlabId);
      });
      el.addEventListener('blur', function () {
        el.classList.remove('pdom-editing');
        commit(el, false);
        if (editingShown === el.swarmlabId) editingShown = 0;
      });
    } else if (item.role === 'heading' || item.role === 'paragraph') {
      el = document.createElement(item.role === 'heading' ? 'h2' : 'p');
    } else {
      el = document.createElement('button');
      el.type = 'button';
      el.addEventListener('click', function () { activate(el.swarmlabId); });
      el.addEventListener('focus', function () { focusItem(el.swarmlabId); });
      // Enter (on its press) and Space (on its release) press the item, as they press a
      // button; they are not the app's shortcuts (Space would also play or pause), so they
      // stop here, and so do the arrows.
      el.addEventListener('keydown', function (e) {
        if (e.key === 'Enter') { e.preventDefault(); activate(el.swarmlabId); }
        if (e.key === ' ') e.preventDefault();
        if (e.key === 'Enter' || e.key === ' ' || e.key.indexOf('Arrow') === 0) e.stopPropagation();
      });
      el.addEventListener('keypress', function (e) {
        if (e.key === 'Enter' || e.key === ' ') e.stopPropagation();
      });
      el.addEventListener('keyup', function (e) {
        if (e.key === ' ') { e.preventDefault(); activate(el.swarmlabId); }
        if (e.key === 'Enter' || e.key === ' ') e.stopPropagation();
      });
    }
    el.className = 'pdom-item';
    el.swarmlabKind = kindOf(item);
    // An item that opens a menu or a list holds it, as ARIA's menus nest (the holder says
    // nothing itself): the popup's entries go in beside the item, which never moves for them
    // (moving the focused element would take its focus).
    if (item.popup) {
      el.swarmlabHolder = document.createElement('div');
      el.swarmlabHolder.setAttribute('role', 'none');
      el.swarmlabHolder.appendChild(el);
    }
    return el;
  }

  function setAttr(el, name, value) {
    if (value === null || value === undefined || value === false) {
      if (el.hasAttribute(name)) el.removeAttribute(name);
    } else {
      var text = value === true ? 'true' : String(value);
      if (el.getAttribute(name) !== text) el.setAttribute(name, text);
    }
  }

  function update(el, item) {
    el.swarmlabId = item.id;
    var text = item.role === 'heading' || item.role === 'paragraph';
    if (text) {
      if (el.textContent !== item.name) el.textContent = item.name;
    } else if (isField(item.role)) {
      setAttr(el, 'aria-label', item.name);
      setAttr(el, 'inputmode', item.numeric ? 'decimal' : null);
      el.swarmlabValue = item.value || '';
      if (document.activeElement !== el && el.value !== el.swarmlabValue) el.value = el.swarmlabValue;
      if (item.role === 'slider') setAttr(el, 'aria-valuetext', item.value || '');
    } else if (item.role === 'combobox') {
      // A combobox takes its name from aria-label, and says its value as its text.
      setAttr(el, 'role', 'combobox');
      setAttr(el, 'aria-label', item.name);
      if (el.textContent !== (item.value || '')) el.textContent = item.value || '';
      setAttr(el, 'aria-haspopup', 'listbox');
      setAttr(el, 'aria-expanded', item.expanded ? 'true' : 'false');
      // Open, it names its list (follow() gives the list this id).
      setAttr(el, 'aria-controls', item.expanded ? 'pdom-list-' + el.swarmlabKey : null);
    } else {
      if (el.textContent !== item.name) el.textContent = item.name;
      setAttr(el, 'role', item.role === 'button' ? null : item.role);
      var checkable = item.role === 'checkbox' || item.role === 'radio' || item.role === 'menuitemcheckbox';
      setAttr(el, 'aria-checked', checkable ? (item.checked ? 'true' : 'false') : null);
      setAttr(el, 'aria-selected', item.role === 'tab' || item.role === 'option' ? (item.checked ? 'true' : 'false') : null);
      setAttr(el, 'aria-haspopup', item.popup ? (item.role === 'combobox' ? 'listbox' : 'menu') : null);
      setAttr(el, 'aria-expanded', item.openable ? (item.expanded ? 'true' : 'false') : null);
    }
    setAttr(el, 'aria-description', item.description || null);
    setAttr(el, 'aria-disabled', item.disabled ? 'true' : null);
    // Scrolled out of its window: the rectangle is where it would be (Tab scrolls it in).
    setAttr(el, 'data-clipped', item.clipped ? 'true' : null);
    // Its text is cut off, or it sticks out of its window sideways (mirrored_item.h).
    setAttr(el, 'data-cut', item.cut ? 'true' : null);
    var s = el.style;
    var left = item.x + 'px', top = item.y + 'px';
    var width = Math.max(item.width, 1) + 'px', height = Math.max(item.height, 1) + 'px';
    if (s.left !== left) s.left = left;
    if (s.top !== top) s.top = top;
    if (s.width !== width) s.width = width;
    if (s.height !== height) s.height = height;
  }

  // ARIA's required parents: tabs are in a tablist, list entries in a listbox, menu entries in
  // a menubar (the menu bar's) or a menu (a popup's). Consecutive items of one kind share one.
  function groupRole(item, opener) {
    if (item.role === 'tab') return 'tablist';
    if (item.role === 'option') return 'listbox';
    if (item.role !== 'menuitem' && item.role !== 'menuitemcheckbox') return null;
    return item.in_popup || opener ? 'menu' : 'menubar';
  }
  function groupFor(key, role) {
    var group = groups.get(key);
    if (!group || group.getAttribute('role') !== role) {
      group = document.createElement('div');
      group.className = 'pdom-group';
      group.setAttribute('role', role);
      groups.set(key, group);
    }
    return group;
  }
  // The name a menu or a listbox is read with: the item that opened it, or for a list in a
  // panel the text just before it ("Shipped presets"), or its window's title.
  function groupName(opener, before, region) {
    if (opener) return opener.getAttribute('aria-label') || opener.textContent;
    if (before && (before.tagName === 'P' || before.tagName === 'H2')) return before.textContent;
    return region;
  }

  // Puts node into container after what was placed there last this frame. Moving the focused
  // element, or what holds it, would take its focus: the others move around it.
  function place(node, container, previous) {
    var after = previous.get(container) || null;
    var wanted = after ? after.nextSibling : container.firstChild;
    if (node !== wanted && !node.contains(document.activeElement)) container.insertBefore(node, wanted);
    previous.set(container, node);
  }

  function keyOf(item, seen) {
    if (item.id) return 'i' + item.id;
    var key = 't' + item.region + '\u0001' + item.role + '\u0001' + item.name;
    var n = (seen.get(key) || 0) + 1;
    seen.set(key, n);
    return key + '\u0001' + n;
  }

  // Once a frame: follow what the app drew.
  function follow() {
    if (!Module.swarmlabMainStarted) return;
    var text = Module.ccall('swarmlab_dom_items', 'string', [], []);
    if (text === lastText) return;
    lastText = text;
    var frame = JSON.parse(text);
    // Plain text cut off (no item's label): for the layout test (tests/web/layout_e2e.mjs).
    Module.swarmlabCutText = frame.cut_text || [];
    if (!root) makeRoot();
    // The reading order before this frame: where the focus goes if its item goes away (placing
    // this frame's items moves the others around the focused one, which then stands last).
    // Only read when the focus is on a mirrored item (follow runs every frame a run plays).
    var before = root.contains(document.activeElement) ? Array.prototype.slice.call(root.querySelectorAll('button, input')) : [];
    // previous: container -> what was placed in it last; counts: how many groups of a kind a
    // container has had this frame (their keys).
    var seenText = new Map(), alive = new Set(), previous = new Map(), counts = new Map(), used = new Set();
    frame.items.forEach(function (item) {
      var key = keyOf(item, seenText);
      var el = elements.get(key);
      if (el && el.swarmlabKind !== kindOf(item)) { (el.swarmlabHolder || el).remove(); el = null; }  // its role changed
      if (!el) { el = make(item); el.swarmlabKey = key; elements.set(key, el); }
      alive.add(key);
      update(el, item);
      // Where it goes: its window's section, or beside the item whose popup it is in.
      var opener = item.popup_of ? elements.get('i' + item.popup_of) : null;
      if (opener && !opener.swarmlabHolder) opener = null;
      var container = opener ? opener.swarmlabHolder : regionFor(item.region);
      var containerKey = opener ? 'h' + opener.swarmlabKey : 'r' + item.region;
      var role = groupRole(item, opener);
      if (role) {
        var last = previous.get(container);
        var group = last && last.className === 'pdom-group' && last.getAttribute('role') === role ? last : null;
        if (!group) {
          var n = (counts.get(containerKey + role) || 0) + 1;
          counts.set(containerKey + role, n);
          group = groupFor(containerKey + '\u0001' + role + '\u0001' + n, role);
          if (role === 'menu' || role === 'listbox') setAttr(group, 'aria-label', groupName(opener, last, item.region));
          if (opener && opener.getAttribute('role') === 'combobox') setAttr(group, 'id', 'pdom-list-' + opener.swarmlabKey);
          place(group, container, previous);
          used.add(group);
        }
        container = group;
      }
      var node = el.swarmlabHolder || el;
      place(node, container, previous);
      if (el.swarmlabHolder) previous.set(el.swarmlabHolder, el);  // its popup goes after it
    });
    groups.forEach(function (group, key) {
      if (used.has(group) || group.contains(document.activeElement)) return;
      groups.delete(key);
      group.remove();
    });
    elements.forEach(function (el, key) {
      if (alive.has(key)) return;
      elements.delete(key);
      if (el === document.activeElement) {
        // The focus stays where it was in the reading order: on the next item one can focus
        // (a pressed Predict button gives way to the feedback; Tab goes on from there).
        var at = before.indexOf(el), next = null;
        for (var i = at + 1; i < before.length && !next; ++i) if (alive.has(before[i].swarmlabKey)) next = before[i];
        for (var j = at - 1; j >= 0 && !next; --j) if (alive.has(before[j].swarmlabKey)) next = before[j];
        if (next && byKeyboard) next.focus(); else document.getElementById('canvas').focus();
      }
      (el.swarmlabHolder || el).remove();
    });
    regions.forEach(function (section, title) {
      if (!section.firstChild) { section.remove(); regions.delete(title); }
    });
    // The regions in reading order too (the one holding the focus stays; the others move).
    var order = [];
    frame.items.forEach(function (item) {
      var section = regions.get(item.region);
      if (section && order.indexOf(section) < 0) order.push(section);
    });
    var holder = document.activeElement && document.activeElement.closest && document.activeElement.closest('.pdom-region');
    order.forEach(function (section, i) {
      if (root.children[i] !== section && section !== holder) root.insertBefore(section, root.children[i] || null);
    });
    // A field tapped on the canvas: its <input> takes the focus, so the phone shows its keyboard.
    if (frame.touch && frame.editing && editingShown !== frame.editing) {
      var field = elements.get('i' + frame.editing);
      if (field && field.tagName === 'INPUT' && document.activeElement !== field) {
        editingShown = frame.editing;
        field.swarmlabValue = frame.text;
        field.focus();
      }
    }
  }
  Module.swarmlabEachFrame = (Module.swarmlabEachFrame || []).concat([follow]);
})();
