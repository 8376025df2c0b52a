MODULE MainModule
  ! Tests: motion and process settings of a handling cell (GripLoad, WorldAccLim, PathAccLim,
  ! StorePath/RestoPath, world zones, servo tuning, displacement) are checked and change
  ! nothing rapidmc observes; MoveExtJ moves only the external axes; the limit functions
  ! give their fixed values.
  PERS loaddata loPart := [2.5,[0,0,50],[1,0,0,0],0,0,0];
  VAR shapedata shBox;
  VAR wztemporary wzBox;
  PERS jointtarget jTrack := [[9E9,9E9,9E9,9E9,9E9,9E9],[1200,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    GripLoad loPart;
    WorldAccLim \On:=3.5;
    PathAccLim TRUE \AccMax:=4, TRUE \DecelMax:=4;
    StorePath;
    RestoPath;
    WZBoxDef \Inside, shBox, [0,0,0], [500,500,500];
    WZLimSup \Temp, wzBox, shBox;
    WZDisable wzBox;
    TuneServo ROB_1, 1, 110 \Type:=TUNE_KP;
    TuneReset;
    PDispSet [[0,0,10],[1,0,0,0]];
    PDispOff;
    MoveExtJ jTrack, vrot50, fine;
    TPWrite "track at " \Num:=CJointT().extax.eax_a;
    TPWrite "max speed " \Num:=MaxRobSpeed();
    TPWrite "torque " \Num:=GetMotorTorque(1);
    GripLoad load0;
  ENDPROC
ENDMODULE
