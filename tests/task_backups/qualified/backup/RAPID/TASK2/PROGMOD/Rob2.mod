MODULE Rob2
  PERS bool go := FALSE;
  VAR num slot := 0;
  PROC main()
    VAR bool flag := FALSE;
    MoveToSlot;
    flag := TRUE;
    back:
    go := TRUE;
  ENDPROC
  PROC MoveToSlot()
    slot := 2;
  ENDPROC
ENDMODULE
