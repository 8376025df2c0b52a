MODULE Rob1
  PERS bool go := FALSE;
  PERS num done := 0;
  VAR num slot := 0;
  PROC main()
    WaitUntil go;
    MoveToSlot;
    done := 1;
  ENDPROC
  PROC MoveToSlot()
    slot := 1;
  ENDPROC
ENDMODULE
