MODULE Reader
  ! shared is written only in the failer's ERROR handler: still a write, so reading it
  ! here depends on the failer.
  PERS num shared := 0;
  VAR num copy := 0;
  VAR num seen := 0;
  PROC main()
    copy := shared;                      ! SHARED
    seen := copy;                        ! VISIBLE
  ENDPROC
ENDMODULE
