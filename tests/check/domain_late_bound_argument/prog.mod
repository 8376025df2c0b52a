MODULE prog
  ! A group input's value passed to a procedure called by a name computed at run time
  ! (%name% args): which routine reads it is unknown, so the input gets no default domain.
  ! Before, the input flow asked the late-bound call for its name and stopped with an
  ! internal error (AttributeError).
  VAR signalgi gi_code;
  VAR num x := 0;
  VAR num code := 0;
  VAR string name := "Show";
  PROC main()
    AliasIO "GI_CODE", gi_code;
    code := gi_code;
    %name% code;
  ENDPROC
  PROC Show(num n)
    x := 10 / (n - 6);
  ENDPROC
ENDMODULE
