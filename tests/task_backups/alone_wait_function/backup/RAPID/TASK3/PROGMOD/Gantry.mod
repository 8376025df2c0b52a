MODULE Gantry
    ! Written for the test (issue 28): the gantry reports through its element of stReact.
    PERS string stReact{3} := ["", "", ""];

    PROC main()
        WHILE TRUE DO
            stReact{3} := "Ready";
            WaitUntil stReact{1} = "Busy";
            stReact{3} := "Busy";
        ENDWHILE
    ENDPROC
ENDMODULE
