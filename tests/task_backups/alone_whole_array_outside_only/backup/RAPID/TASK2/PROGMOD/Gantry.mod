MODULE Gantry
    ! Written for the test (issue 28): the gantry reports its four stations.
    PERS string stState{4} := ["", "", "", ""];

    PROC main()
        FOR i FROM 1 TO 4 DO
            stState{i} := "Ready";
        ENDFOR
    ENDPROC
ENDMODULE
