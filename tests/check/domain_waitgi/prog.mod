MODULE DomainWaitGI
    ! The cell waits for start code 5 on a group input, then for any code but 5.
    ! Both waits only compare the input with 5: the derived domain is {0, 4, 5, 6}.
    VAR signalgi gi_start;
    VAR num phase := 0;

    PROC main()
        AliasIO "GI_START", gi_start;
        WHILE TRUE DO
            WaitGI gi_start, 5;
            phase := 1;
            WaitGI gi_start \NOTEQ, 5;
            phase := 0;
        ENDWHILE
    ENDPROC
ENDMODULE
