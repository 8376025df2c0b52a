MODULE MainModule
  ! Tests: WaitGI and WaitAI wait for a group value or an analog level (\GT, \LT); a wait
  ! not met within \MaxTime raises ERR_WAIT_MAXTIME; MoveLGO and MoveLAO set their output at
  ! the target; ORobT gives the point back (no displacement is active).
  PERS robtarget pDrop := [[400,100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget pOrig;
  PROC main()
    WaitGI giRecipe, 3;
    TPWrite "recipe 3 selected";
    WaitAI aiPressure \GT, 2.5;
    TPWrite "pressure above 2.5";
    MoveLGO pDrop, v200, fine, tool0, goStation, 5;
    TPWrite "station " \Num:=GOutput(goStation);
    MoveLAO pDrop, v200, fine, tool0, aoFlow, 1.5;
    TPWrite "flow " \Num:=AOutput(aoFlow);
    pOrig := ORobT(pDrop \InPDisp);
    TPWrite "x " \Num:=pOrig.trans.x;
    WaitLow;
  ENDPROC
  PROC WaitLow()
    WaitAI aiPressure \LT, 1 \MaxTime:=2;
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME TPWrite "pressure stayed high";
    RETURN;
  ENDPROC
ENDMODULE
