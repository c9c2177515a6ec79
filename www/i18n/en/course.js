// English texts of course systems: a SCORM package's bar (its exercises, the score, whether the
// course system took it), the H5P content type's messages, and why a package cannot be made or read.
// Keys: course.*

export default {
  'course.bar': 'Course activity',
  'course.exercise': 'Exercise',
  'course.score': 'Score so far: {raw} of {max} conditions met.',
  'course.noRuntime': 'No course system records here: the exercises work, nothing is recorded.',
  'course.connected':
    'The course system (SCORM {standard}) records each check; the attempt stays open until every exercise is solved or you end it.',
  'course.scoreRecorded': 'Recorded in this attempt: {raw} of {max} conditions met.',
  'course.ended': 'You ended this attempt: what you check now is not recorded.',
  'course.review':
    'The course system opened this attempt for review: you see your recorded work, and nothing you do now is recorded.',
  'course.browse': 'The course system opened this activity for browsing: nothing you do is recorded.',
  'course.noCredit':
    'This attempt is not graded (the course system gives it no credit): your work is kept, no score is recorded.',
  'course.restored':
    'Your work was restored from this browser: the course system had not kept it (its last saving failed).',
  'course.end': 'End the attempt',
  'course.endConfirm':
    'End the attempt with {raw} of {max} conditions met? Your score is then final, and the course system will open it for review.',
  'course.endYes': 'End it',
  'course.endNo': 'Keep working',
  'course.notStarted':
    'The course system did not start the session ({call}: error {code}, “{text}”): nothing you do here is recorded. Reload the page, or tell your lecturer.',
  'course.startThrew':
    'The course system could not be reached ({call}: “{text}”): nothing you do here is recorded. Reload the page, or tell your lecturer.',
  'course.shownDescription': '(solution shown: not counted)',
  'course.h5pPending':
    'Recorded when you solve the exercise or end the attempt (so far {raw} of {max} conditions met).',
  'course.h5pRecorded': 'Recorded: {raw} of {max} conditions met. Start over to make a new attempt.',
  'course.activityTitle': 'Activity title (as the course shows it)',
  'course.solution': 'The solution may be shown',
  'course.solution.after': 'after {count:check:checks} without solving it',
  'course.solution.never': 'never',
  'course.solution.atOnce': 'at once',
  'course.draw': 'Numbers drawn',
  'course.draw.attempt': 'per attempt',
  'course.draw.learner': 'per learner (the same at every launch of hers; a review shows them too)',
  'course.packageOf.scorm12': 'SCORM 1.2 package of {what}',
  'course.packageOf.scorm2004': 'SCORM 2004 package of {what}',
  'course.packageOf.h5p': 'H5P file of {what}',
  'course.what.one': '‘{title}’',
  'course.what.more': '‘{title}’ + {count} more',
  'course.what.titled': '“{title}” ({count:exercise:exercises})',
  'course.recorded': 'Recorded in the course at {time}.',
  'course.learner': 'Student: {name}.',
  'course.broken': 'This package’s exercises cannot be read ({reason}): ask your lecturer for a new package.',
  'course.refused':
    'The course system did not take the result ({call}: error {code}, “{text}”). Your work stays here and is sent again with your next check.',
  'course.threw':
    'The course system failed ({call}: “{text}”). Your work stays here and is sent again with your next check.',
  'course.h5pBroken': 'This exercise cannot be shown: {reason}.',
  'course.h5pRefused': 'The course system did not take the result ({detail}). Your work stays here.',
  'course.readers': 'What readers may do',
  'course.reader.edit': 'drag the points (edit the geometry)',
  'course.reader.controls': 'see and use the controls',
  'course.reader.text': 'see the explanation',
  'course.reader.leave': 'leave the exercise',
  'course.packages':
    'For a course system that records grades: a SCORM package (every course system imports one) or an H5P file (Moodle, ILIAS; an administrator allows its content type once).',
  'course.package.scorm12': 'SCORM 1.2 package',
  'course.package.scorm2004': 'SCORM 2004 package',
  'course.package.h5p': 'H5P file',
  'course.made.scorm':
    'Made: upload the zip file as a SCORM package (ruledlab’s book, “In a course system”, says how).',
  'course.made.h5p': 'Made: upload the .h5p file as H5P content (ruledlab’s book, “In a course system”, says how).',
  'course.more': 'More exercises in the SCORM package (one activity, the score their sum; up to {max} in all)',
  'course.notMade': 'Not made: {reason}.',
  'course.error.notZip': 'this is not a zip file: {detail}',
  'course.error.tooLarge': 'the package is larger than {max} MB',
  'course.error.badName': 'the package holds a file outside its folder: “{name}”',
  'course.error.missing': 'the package lacks “{name}”',
  'course.error.noTasks': 'a package needs 1 to {max} exercises',
  'course.error.standard': 'the standard is “scorm12” or “scorm2004”, not “{standard}”',
  'course.error.notOneFile': 'the page given is not ruledlab’s one-file build',
  'course.error.noPage': 'ruledlab’s one-file page (dist/ruledlab.html) is not there to go into the package',
  'course.error.noScript': 'ruledlab’s embed script (dist/ruledlab-embed.js) is not there to go into the file',
  'course.error.notH5p': 'this .h5p file holds no ruledlab exercise ({detail})',
};
