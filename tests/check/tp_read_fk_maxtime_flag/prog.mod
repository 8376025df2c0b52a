MODULE TpReadFkMaxTimeFlag
    ! \MaxTime with \BreakFlag: a timeout writes ERR_TP_MAXTIME to the flag and leaves the
    ! answer as it was; without the flag it would be an error (see the other cases).
    VAR num key := 0;
    VAR errnum reason := 0;

    PROC main()
        TPReadFK key, "Go?", "Go", stEmpty, stEmpty, stEmpty, stEmpty \MaxTime:=10 \BreakFlag:=reason;
    ENDPROC
ENDMODULE
