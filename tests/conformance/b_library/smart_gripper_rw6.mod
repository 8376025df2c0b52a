MODULE smart_gripper_rw6
  ! Tests: the RobotWare 6 SmartGripper names public YuMi backups call (issue 28) load and
  ! run as their Hand_* successors do: no effect, the position reads 0.
  VAR num force := 15;

  PROC main()
    g_Init \maxSpd:=20, \holdForce:=20;
    g_Calibrate \Grip;
    g_GripIn \holdForce:=force \targetPos:=5 \NoWait;
    g_GripOut \NoWait;
    g_MoveTo 15;
    g_MoveTo(10);
    g_JogIn;
    g_JogOut;
    g_SetForce force;
    TPWrite "gripper at " + NumToStr(g_GetPos(), 2);
  ENDPROC
ENDMODULE
