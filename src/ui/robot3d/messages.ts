import { defineMessages } from "../../i18n/catalogue.ts";
import type { Translator } from "../../i18n/translate.ts";

/** The 3D robot's words: the canvas, the motion preview's controls and the "Robot in 3D" card. */
export const robot3dMessages = defineMessages({
  // The canvas (robot-canvas.ts, errors.ts)
  "robot3d.loading": { en: "Loading the 3D view…", ko: "3D 보기를 불러오는 중…" },
  "robot3d.noWebgl": {
    en: "The 3D view needs WebGL 2, which this browser does not offer here (it may be switched off, or the graphics driver blocked). The scene table describes the motion in text.",
    ko: "3D 보기에는 WebGL 2가 필요한데, 이 브라우저에서는 지금 쓸 수 없어요 (꺼져 있거나 그래픽 드라이버가 막혀 있을 수 있어요). 장면 표에서 모션을 글로 볼 수 있어요.",
  },
  "robot3d.loadFailed": {
    en: "The 3D view could not be loaded (offline since the panel was opened?). The scene table describes the motion in text.",
    ko: "3D 보기를 불러오지 못했어요 (패널을 연 뒤 오프라인이 되었나요?). 장면 표에서 모션을 글로 볼 수 있어요.",
  },

  // The motion preview (motion-preview.ts)
  "robot3d.noScenes": { en: "no scenes", ko: "장면 없음" },
  "robot3d.scene": { en: "scene {scene}, {name}", ko: "장면 {scene}, {name}" },
  "robot3d.sceneEnd": { en: "end of scene {scene}, {name}", ko: "장면 {scene} 끝, {name}" },
  "robot3d.backToStart": { en: "Back to the start", ko: "처음으로" },
  "robot3d.nextScene": { en: "Next scene", ko: "다음 장면" },
  "robot3d.pause": { en: "Pause", ko: "일시 정지" },
  "robot3d.playAgain": { en: "Play again", ko: "다시 재생" },
  "robot3d.play": { en: "Play", ko: "재생" },
  "robot3d.time": { en: "Time", ko: "시간" },
  "robot3d.reducedHint": {
    en: "Reduced motion is on: Next scene shows each scene's pose without animating.",
    ko: "동작 줄이기가 켜져 있어요. '다음 장면'을 누르면 움직이는 화면 없이 각 장면의 자세를 보여 줘요.",
  },
  "robot3d.keysHint": {
    en: "Time: arrow keys move {step}, Page Up and Page Down a scene. Turn the robot: drag it, or focus it and use the arrow keys.",
    ko: "시간: 화살표 키로 {step}씩, Page Up과 Page Down으로 한 장면씩 움직여요. 로봇 돌리기: 로봇을 끌거나, 로봇을 선택한 뒤 화살표 키를 눌러 주세요.",
  },

  // The "Robot in 3D" card (live-robot.ts)
  "robot3d.live.title": { en: "Robot in 3D", ko: "3D 로봇" },
  "robot3d.live.show": { en: "Show the robot in 3D", ko: "로봇을 3D로 보기" },
  "robot3d.live.hide": { en: "Hide the robot in 3D", ko: "3D 로봇 숨기기" },
  "robot3d.live.demoCaption": { en: "Demo robot, live", ko: "데모 로봇, 실시간" },
  "robot3d.live.demoLabel": {
    en: "3D view of the demo robot, live: it follows the simulated servos as they move; {textVersion}",
    ko: "데모 로봇의 실시간 3D 보기: 가상 서보가 움직이는 대로 따라가요; {textVersion}",
  },
  "robot3d.live.demoText": {
    en: "The demo robot's servos are simulated in this page, so the picture follows them as they move (motions, servo moves). A robot on a cable cannot be followed during a motion: it answers nothing but Basic posture (7) while it plays.",
    ko: "데모 로봇의 서보는 이 페이지 안에서 가상으로 움직여서, 그림이 그 움직임(모션, 서보 이동)을 그대로 따라가요. 케이블로 연결한 로봇은 모션 중에는 따라갈 수 없어요. 모션을 재생하는 동안에는 기본 자세(7) 명령에만 응답하기 때문이에요.",
  },
  "robot3d.live.noneRead": {
    en: "No positions read yet: drawn in the basic posture",
    ko: "아직 읽은 위치가 없어요: 기본 자세로 그렸어요",
  },
  "robot3d.live.lastRead": { en: "Last read positions", ko: "마지막으로 읽은 위치" },
  "robot3d.live.lastReadAt": { en: "Last read positions, {time}", ko: "마지막으로 읽은 위치, {time}" },
  "robot3d.live.noneReadText": {
    en: "The panel has not read this robot's servos in this connection, so every joint is drawn at the basic posture, not where the robot is. Read them in the Servos view (Start servo control).",
    ko: "이번 연결에서 패널이 이 로봇의 서보를 읽지 않아서, 모든 관절을 로봇의 실제 자세가 아니라 기본 자세로 그렸어요. 서보 화면에서 읽어 주세요 (서보 제어 시작).",
  },
  "robot3d.live.idList": { en: "{list} and {last}", ko: "{list}, {last}" },
  "robot3d.live.unreadOne": {
    en: "Servo {ids} was never read (or did not answer): drawn at the basic posture, not where it is.",
    ko: "서보 {ids}번은 읽지 못했어요 (또는 응답하지 않았어요). 실제 위치가 아니라 기본 자세로 그렸어요.",
  },
  "robot3d.live.unreadMany": {
    en: "Servos {ids} were never read (or did not answer): drawn at the basic posture, not where they are.",
    ko: "서보 {ids}번은 읽지 못했어요 (또는 응답하지 않았어요). 실제 위치가 아니라 기본 자세로 그렸어요.",
  },
  "robot3d.live.noneReadLabel": {
    en: "3D view of the robot in the basic posture: none of its positions has been read",
    ko: "기본 자세로 그린 로봇의 3D 보기: 읽은 위치가 하나도 없어요",
  },
  "robot3d.live.label": {
    en: "3D view of the robot at its last read positions",
    ko: "마지막으로 읽은 위치에 있는 로봇의 3D 보기",
  },
  "robot3d.live.labelAt": {
    en: "3D view of the robot at its last read positions, {time}",
    ko: "마지막으로 읽은 위치({time})에 있는 로봇의 3D 보기",
  },
  "robot3d.live.unreadLabelOne": {
    en: "servo {ids} never read, drawn at the basic posture",
    ko: "서보 {ids}번은 읽지 않아 기본 자세로 그림",
  },
  "robot3d.live.unreadLabelMany": {
    en: "servos {ids} never read, drawn at the basic posture",
    ko: "서보 {ids}번은 읽지 않아 기본 자세로 그림",
  },
  "robot3d.live.motionPlaying": {
    en: "A motion is playing. The robot answers nothing but Basic posture (7) until it ends, so its servos cannot be read: the picture does not follow the motion and still shows the positions read before.",
    ko: "모션을 재생하고 있어요. 끝날 때까지 로봇은 기본 자세(7) 명령에만 응답해서 서보를 읽을 수 없어요. 그림은 모션을 따라가지 않고 전에 읽은 위치를 그대로 보여 줘요.",
  },
  "robot3d.live.notLive": {
    en: "The picture shows what the robot last reported, not a live view: during a motion the robot's servos cannot be read (it answers nothing but Basic posture (7) while it plays), and a hand or a motion may have moved them since.",
    ko: "그림은 실시간 화면이 아니라 로봇이 마지막으로 알려 준 상태예요. 모션 중에는 로봇의 서보를 읽을 수 없고 (재생하는 동안에는 기본 자세(7) 명령에만 응답해요), 그 뒤에 손이나 모션으로 서보가 움직였을 수 있어요.",
  },
  "robot3d.live.standardZeros": {
    en: "This robot's zeros have not been read in this connection, so angles are measured from the standard zero table.",
    ko: "이번 연결에서 이 로봇의 영점을 읽지 않아서, 각도는 표준 영점 표를 기준으로 재요.",
  },
});

export type Robot3dTranslator = Translator<typeof robot3dMessages>;
