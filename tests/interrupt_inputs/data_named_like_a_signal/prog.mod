MODULE Cell
    ! Module data named like a configured signal, aliased to another one: the interrupt
    ! is ordered on diOther's edges.
    VAR signaldi diReset;
    VAR intnum stop_int;
    VAR bool stopped := FALSE;

    PROC main()
        AliasIO "diOther", diReset;
        CONNECT stop_int WITH OnStop;
        ISignalDI diReset, 1, stop_int;
        WHILE TRUE DO
            WaitTime 1;
        ENDWHILE
    ENDPROC

    TRAP OnStop
        stopped := TRUE;
    ENDTRAP
ENDMODULE
