MODULE Master
    ! Written for the test (issue 28): an operator picks a job; master and robot task
    ! meet at that job's barrier.
    VAR syncident job_a;
    VAR syncident job_b;
    VAR syncident job_c;
    VAR syncident job_d;
    VAR syncident job_e;
    PERS tasks both{2} := [["T_MASTER"], ["T_ROB"]];
    VAR num answer := 0;
    VAR num slots{4} := [1, 2, 3, 4];

    PROC main()
        WHILE TRUE DO
            TPReadFK answer, "Job?", "A", "B", "C", "D", "E";
            TEST answer
            CASE 1:
                WaitSyncTask job_a, both;
            CASE 2:
                WaitSyncTask job_b, both;
            CASE 3:
                WaitSyncTask job_c, both;
            CASE 4:
                WaitSyncTask job_d, both;
            CASE 5:
                WaitSyncTask job_e, both;
                TPWrite "slot" \Num:=slots{answer};
            ENDTEST
        ENDWHILE
    ENDPROC
ENDMODULE
