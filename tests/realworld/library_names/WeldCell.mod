MODULE WeldCell
  ! Tests: a program in the style of the public cells the survey of issue 8 found stopping at
  ! the first predefined name rapidmc lacked: arc welding data, the sensor interface, the
  ! FlexPendant menu, error reports as interrupts, data reached by name, stored paths, search,
  ! Integrated Vision, message queues, the SmartGripper.  It must load and run.
  TASK PERS seamdata seamMain := [0.5,0.5,[5,0,24,120,0,0,0,0,0],0.5,1,10,0,5,[5,0,24,120,0,0,0,0,0],0,1,[5,0,24,120,0,0,0,0,0],0,0,[0,0,0,0,0,0,0,0,0],0];
  TASK PERS welddata weldMain := [8,0,[5,0,24,120,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS sensor sensLaser := [-1,-1,0];
  PERS loaddata loTorch := [3,[0,0,120],[1,0,0,0],0,0,0];
  PERS tooldata tTorch := [TRUE,[[0,0,350],[1,0,0,0]],[3,[0,0,120],[1,0,0,0],0,0,0]];
  PERS robtarget pSeamStart := [[600,0,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pSeamEnd := [[600,300,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST listitem liJobs{2} := [["", "Weld seam"], ["", "Clean torch"]];
  VAR intnum irErrors;
  VAR trapdata tdLast;
  VAR errdomain edLast;
  VAR errtype etLast;
  VAR num nErrorId;
  VAR speedlimdata sldLimit;
  VAR cameradev camSeam;
  VAR datapos dpBlock;
  VAR itmsrc isConveyor;
  VAR menudata mdMain;
  VAR jointgroup jgArm;
  VAR testsignal tsSpeed := 0;
  VAR robtarget pTouch;
  VAR num nJob;
  VAR num nSeamLength;
  VAR rmqslot rsLogger;

  PROC main()
    CONNECT irErrors WITH trErrors;
    IError COMMON_ERR, TYPE_ERR, irErrors;
    GripLoad loTorch;
    WorldAccLim \On:=4;
    PathAccLim TRUE \AccMax:=3, TRUE \DecelMax:=3;
    nJob := UIListView(\Header:="Job", liJobs \Icon:=iconInfo);
    IF nJob = 1 THEN
      WeldSeam;
    ELSE
      TPWrite "cleaning";
    ENDIF
    IF IsFile("HOME:/weld.log") TPWrite "log found";
    RMQFindSlot rsLogger, "RMQ_T_LOG";
    TPWrite "max speed " \Num:=MaxRobSpeed();
    TPWrite "motor torque " \Num:=GetMotorTorque(\MecUnit:=ROB_1, 2);
    Hand_MoveTo 10;
  ENDPROC

  PROC WeldSeam()
    SearchL \Stop, diTouch, pTouch, pSeamStart, v100, tTorch;
    MoveL pTouch, v100, fine, tTorch;
    StorePath;
    MoveExtJ [[9E9,9E9,9E9,9E9,9E9,9E9],[0,9E9,9E9,9E9,9E9,9E9]], vrot10, fine;
    RestoPath;
    GetDataVal "nSeamLength", nSeamLength;
    SetDataVal "nSeamLength", 300;
    TPWrite "seam at speed " \Num:=weldMain.weld_speed;
    MoveL pSeamEnd, v100, fine, tTorch;
    WriteCfgData "/MOC/MOTION_SYSTEM/system_1", "min_temp_cabinet", 5;
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      TPWrite "no seam found";
      RETURN;
    ENDIF
  ENDPROC

  TRAP trErrors
    GetTrapData tdLast;
    ReadErrData tdLast, edLast, nErrorId, etLast;
    ErrRaise "ERR_WELD", 7001, "Weld", ERRSTR_TASK, "Arc error", ERRSTR_CONTEXT, ERRSTR_EMPTY \W;
  ENDTRAP
ENDMODULE
