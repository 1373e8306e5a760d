import type { Notice } from "../../notices.ts";

/** The Robot view's part of the app state: the device card's figures. Reset with every connection. */
export interface DeviceInfoState {
  errorCode?: number;
  freeMotion?: number;
  freeAction?: number;
  loading: boolean;
  readAt?: number;
  notice?: Notice;
}

export function initialDeviceInfo(): DeviceInfoState {
  return { loading: false };
}
