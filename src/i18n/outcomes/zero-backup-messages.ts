import { defineMessages } from "../catalogue.ts";

/**
 * Why a zero backup file was refused (the parser's `BackupProblem`, src/protocol/zeros-backup.ts), for a reader
 * of Korean: `zerosBackupRefusalText` (zero-backup-words.ts) says it from the problem for `rbc zeros write --from`
 * and the panel's Zeros view alike. In English a person reads the parser's own sentence, which names more (the
 * format found, the version, the servos): the English here is its gist.
 */
export const zeroBackupOutcomeMessages = defineMessages({
  "outcome.zerosBackup.notJson": {
    en: "This file is not a zero backup: it is not JSON text.",
    ko: "영점 백업 파일이 아니에요(JSON 텍스트가 아님). 이 패널이 저장한 파일을 골라 주세요. 이름은 rbc-zeros-<시리얼 번호>-<날짜>.json 같은 모양이에요.",
  },
  "outcome.zerosBackup.wrongFormat": {
    en: "This file is JSON but not an RBC zero backup.",
    ko: "JSON 파일이지만 RBC 영점 백업이 아니에요. 이 패널이 저장한 파일을 골라 주세요. 이름은 rbc-zeros-<시리얼 번호>-<날짜>.json 같은 모양이에요.",
  },
  "outcome.zerosBackup.wrongVersion": {
    en: "This backup is of a version that cannot be read.",
    ko: "읽을 수 없는 버전의 백업이에요.",
  },
  "outcome.zerosBackup.wrongCount": {
    en: "This backup does not hold exactly 16 values, one per servo 0-15.",
    ko: "영점 표에는 서보 0-15마다 하나씩 정확히 16개의 값이 있어야 하는데, 이 백업은 그렇지 않아요.",
  },
  "outcome.zerosBackup.outOfRange": {
    en: "The robot would refuse this backup's zeros (servo {servos}).",
    ko: "로봇이 이 백업의 영점을 거부할 거예요. 서보 {servos}의 값이 정수가 아니거나 허용 범위를 벗어나요.",
  },
  "outcome.zerosBackup.outOfRangeSome": {
    en: "The robot would refuse this backup's zeros.",
    ko: "로봇이 이 백업의 영점을 거부할 거예요. 정수가 아니거나 기준 영점의 ±15를 벗어난 값이 있어요.",
  },
  "outcome.zerosBackup.damaged": {
    en: "This backup file is damaged.",
    ko: "이 백업 파일은 손상됐어요.",
  },
});
