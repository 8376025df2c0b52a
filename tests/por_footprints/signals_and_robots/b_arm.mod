MODULE ArmTwo
  CONST robtarget pHome := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR num seen := 0;
  PROC main()
    MoveJ pHome, v100, fine, tool0;      ! LOCAL
    IF doShared = 1 THEN                 ! SHARED
      seen := 1;                         ! LOCAL
    ENDIF
    SetDO doLamp, 1;                     ! SHARED
  ENDPROC
ENDMODULE
