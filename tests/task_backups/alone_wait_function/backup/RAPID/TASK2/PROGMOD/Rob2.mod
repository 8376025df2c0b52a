MODULE Rob2
    ! Written for the test (issue 28): robot 2 reports through its element of stReact.
    PERS string stReact{3} := ["", "", ""];

    PROC main()
        WHILE TRUE DO
            stReact{2} := "Ready";
            WaitUntil stReact{1} = "Busy";
            stReact{2} := "Busy";
        ENDWHILE
    ENDPROC
ENDMODULE
