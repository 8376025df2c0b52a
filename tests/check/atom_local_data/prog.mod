MODULE AtomLocalData
    ! Atoms see global data only: not routine data, not LOCAL module data.
    LOCAL VAR num hidden := 0;

    PROC main()
        VAR num steps := 0;
        steps := steps + 1;
        hidden := steps;
    ENDPROC
ENDMODULE
