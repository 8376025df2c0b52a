MODULE ArmOne
  ! Signals and robots: a signal read conflicts only with the tasks whose code may set
  ! it, a robot reading only with the task moving that robot (two motion tasks: one
  ! robot each; a task name no task has reads the caller's robot).  A move of a robot no
  ! other task reads is its task's own.
  CONST robtarget pHome := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR num seen := 0;
  VAR robtarget here;
  VAR jointtarget joints;
  PROC main()
    MoveJ pHome, v100, fine, tool0;      ! LOCAL
    IF diStart = 1 seen := 1;            ! LOCAL
    IF DInput(diStart) = 1 seen := 2;    ! LOCAL
    IF doLamp = 1 THEN                   ! SHARED
      seen := 3;                         ! LOCAL
    ENDIF
    IF doOwn = 1 seen := 4;              ! LOCAL
    Set doOwn;                           ! LOCAL
    SetDO doOwn, seen MOD 2;             ! LOCAL
    SetDO \SDelay:=0.5, doOwn, 1;        ! SHARED
    PulseDO doOwn;                       ! SHARED
    Reset doShared;                      ! SHARED
    Reset doWatched;                     ! VISIBLE
    here := CRobT();                     ! LOCAL
    joints := CJointT(\TaskName:="T_GANTRY"); ! LOCAL
    joints := CJointT(\TaskName:="task 3 (c_logger)"); ! LOCAL
  ENDPROC
ENDMODULE
