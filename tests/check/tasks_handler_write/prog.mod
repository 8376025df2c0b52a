MODULE Reader
  PERS num shared := 0;
  VAR num copy := 0;
  VAR num seen := 0;
  PROC main()
    copy := shared;
    seen := copy;
  ENDPROC
ENDMODULE
