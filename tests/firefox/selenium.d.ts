// selenium-webdriver ships no declarations, and @types/selenium-webdriver does not cover the
// BiDi log inspector this test needs; the modules are typed `any` here, on purpose.
declare module 'selenium-webdriver';
declare module 'selenium-webdriver/firefox.js';
declare module 'selenium-webdriver/bidi/logInspector.js';
