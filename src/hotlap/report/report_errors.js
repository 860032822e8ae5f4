// hotlap report: counts script errors from the very start, before Chart.js and the page's own
// script run, and shows the count in #hotlap-status (data-errors), which the tests read.
(function () {
  'use strict';
  const report = { errors: [], rendered: 0 };
  window.hotlapReport = report;
  report.show = function () {
    const status = document.getElementById('hotlap-status');
    if (!status) return;
    const expected = Number(status.getAttribute('data-expected'));
    status.setAttribute('data-rendered', String(report.rendered));
    status.setAttribute('data-errors', String(report.errors.length));
    let text = report.rendered + ' of ' + expected + ' charts rendered, ' +
      report.errors.length + ' script error' + (report.errors.length === 1 ? '' : 's');
    if (report.errors.length > 0) text += ': ' + report.errors.join(' | ');
    status.textContent = text;
    status.className = report.errors.length > 0 || report.rendered !== expected ? 'bad' : 'good';
  };
  report.fail = function (message) {
    report.errors.push(String(message));
    report.show();
  };
  window.addEventListener('error', function (event) {
    report.fail(event.message || ('cannot load ' + (event.target && event.target.src)));
  }, true);
  window.addEventListener('unhandledrejection', function (event) {
    report.fail('unhandled rejection: ' + event.reason);
  });
  const consoleError = console.error;
  console.error = function () {
    report.fail('console.error: ' + Array.prototype.join.call(arguments, ' '));
    consoleError.apply(console, arguments);
  };
})();
