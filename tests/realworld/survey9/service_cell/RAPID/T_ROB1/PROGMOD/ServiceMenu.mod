MODULE ServiceMenu
  ! Production Manager style service menu, a touch sensing search on a PERS flag, an
  ! inverse-kinematics check and a routine left unfinished in the editor
  TASK PERS menudata mdMoveHome := ["Move to Home","","MoveHome",1,"",255,TRUE,1,0,FALSE,210];
  TASK PERS menudata mdTouchUp := ["Touch up part","","TouchUp",1,"",255,TRUE,2,0,FALSE,211];
  PERS bool bWireTouch := FALSE;
  PERS btnres answer := 0;
  PERS robtarget pSafe := [[600,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pPart := [[700,100,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pSeam := [[700,300,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS pos pMiddle := [0,0,0];
  PERS num nReachable := 0;
  VAR robtarget pFound;
  VAR jointtarget jCheck;
  VAR errnum errIk;

  PROC main()
    UIMsgBox \Header:="Service", "Run " + mdTouchUp.description + "?" \Buttons:=btnOKCancel \Result:=answer;
    IF answer = resOK THEN
      %mdTouchUp.c3%;
    ENDIF
    %mdMoveHome.c3%;
  ENDPROC

  PROC MoveHome()
    MoveSafe tool0, wobj0;
  ENDPROC

  PROC TouchUp()
    jCheck := CalcJointT(pPart, tool0 \WObj:=wobj0 \ErrorNumber:=errIk);
    IF errIk = ERR_ROBLIMIT THEN
      nReachable := 0;
      RETURN;
    ENDIF
    nReachable := 1;
    SearchL \Stop, bWireTouch, pFound, pPart, v100, tool0;
    Incr nTouchCount;
    pMiddle := (pFound.trans + pSeam.trans) / 2;
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      RETURN;
    ENDIF
  ENDPROC

  PROC NewRoutine()
    <SMT>
  ENDPROC
ENDMODULE
