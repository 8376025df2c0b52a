MODULE Rob1
  ! Two motion tasks take turns; each moves relative to where its own robot is.
  PERS bool bTurn := TRUE;
  PROC main()
    WHILE TRUE DO
      WaitUntil bTurn;
      MoveL Offs(CRobT(), 0, 0, 100), v100, fine, tool0;
      bTurn := FALSE;
    ENDWHILE
  ENDPROC
ENDMODULE
