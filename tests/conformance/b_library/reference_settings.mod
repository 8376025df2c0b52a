MODULE MainModule
  ! Tests: names added from public evidence for the reference (issue 8, item 1) load and
  ! change nothing rapidmc observes: SoftMove's CSSAct and CSSForceOffsetAct with the
  ! directions CSS_XZ (5) and CSS_NEGX, CSSDeactMoveL moving the robot like MoveL, the weld
  ! recovery pair RecoveryPosSet/RecoveryPosReset, UIMsgWrite/UIMsgWriteAbort, a brake check,
  ! FricIdInit, the sensor interface (SenDevice, DropSensor), Prox recording and a named
  ! camera parameter.
  CONST robtarget pOver := [[400,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR cameradev camera;
  PROC main()
    VAR robtarget here;
    CSSAct \RefFrame:=CSS_REFFRAME_TOOL, CSS_XZ \StiffnessNonSoftDir:=30 \Stiffness:=0 \AllowMove;
    CSSForceOffsetAct CSS_NEGX, 12;
    CSSDeactMoveL pOver, v100, tool0 \WObj:=wobj0;
    here := CRobT(\Tool:=tool0 \WObj:=wobj0);
    TPWrite "z " \Num:=here.trans.z;
    TPWrite "soft dir " \Num:=CSS_XZ;
    RecoveryPosSet;
    RecoveryPosReset;
    UIMsgWrite "Header", "Message";
    UIMsgWriteAbort;
    CyclicBrakeCheck;
    FricIdInit;
    SenDevice "ssc1";
    DropSensor ROB_1;
    PrxActivRecord ROB_1, 0.1;
    PrxSetSyncalarm ROB_1, 2 \NoPulse;
    PrxStoreRecord ROB_1, 0, "profile.log";
    CamSetParameter camera, "Pattern" \NumVal:=3;
    TPWrite "done";
  ENDPROC
ENDMODULE
