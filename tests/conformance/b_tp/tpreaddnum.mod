MODULE MainModule
  ! Tests: TPReadDnum shows its prompt and stores a dnum answer with double precision.
  PROC main()
    VAR dnum answer;
    VAR dnum one := 1;
    TPReadDnum answer, "Serial number?";
    TPWrite "serial=" \Dnum:=answer;
    TPWrite "next=" \Dnum:=answer + one;
  ENDPROC
ENDMODULE
