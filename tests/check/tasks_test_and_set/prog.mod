! Two tasks share a tool changer; WaitTestAndSet on the shared PERS lock lets one in at a time.
MODULE prog
  PERS bool lock := FALSE;
  PERS num inside := 0;
  PERS num uses := 0;
  PROC main()
    FOR i FROM 1 TO 2 DO
      WaitTestAndSet lock;
      inside := inside + 1;
      uses := uses + 1;
      inside := inside - 1;
      lock := FALSE;
    ENDFOR
  ENDPROC
ENDMODULE
