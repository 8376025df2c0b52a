MODULE Still
  VAR num count := 0;
  PROC main()
    count := count + 1;                  ! LOCAL
  ENDPROC
ENDMODULE
