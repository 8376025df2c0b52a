MODULE yumi_arm_stream
  ! A YuMi arm handing its joints to an external controller over EGM: the arm's
  ! mechanical unit is ROB_L, a name of the YuMi motion configuration.
  VAR egmident egmArm;
  CONST egm_minmax egmLimit := [-0.5,0.5];
  PERS bool bStreaming := FALSE;

  PROC main()
    EGMGetId egmArm;
    IF EGMGetState(egmArm) <= EGM_STATE_CONNECTED THEN
      EGMSetupUC ROB_L, egmArm, "default", "UCdeviceL:" \Joint;
    ENDIF
    EGMActJoint egmArm \J1:=egmLimit \J2:=egmLimit \J7:=egmLimit;
    bStreaming := TRUE;
    EGMRunJoint egmArm, EGM_STOP_HOLD \J1 \J2 \J7 \CondTime:=5;
    bStreaming := FALSE;
    EGMReset egmArm;
  ENDPROC
ENDMODULE
